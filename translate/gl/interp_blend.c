/* interp_blend.c: blending and logic ops (GL 2.1 4.1.8, 4.1.10), as Mesa's
 * blend.c and logicop.c hold them: glBlendFunc(Separate), glBlendEquation
 * (Separate), glBlendColor, glLogicOp, and how a draw's colours show what
 * lies behind it.
 *
 * POV-Ray shows what is behind a surface through its pigment's filter F
 * and transmit T: the pixel is (1 - F - T) C + (F C + T) behind, channel by
 * channel. GL's blend of a source colour c over a destination d is
 * E + M d per channel, for every equation but GL_MIN and GL_MAX and every
 * factor but those of d's own colour or alpha applied to d: E the source
 * term, M the destination's weight (GL_DST_COLOR as source factor moves c
 * into M). Where M is one number for all channels, F = 0, T = M, C = E /
 * (1 - T) (a colour beyond 1, or below 0 under GL_FUNC_REVERSE_SUBTRACT,
 * which POV-Ray keeps as it is and clamps at the pixel, as GL clamps the
 * blended value); where E is 0 (glBlendFunc(GL_ZERO, GL_SRC_COLOR),
 * GL_DST_COLOR with GL_ZERO: the multiplying blends), F = 1, C = M; and
 * where M is affine in E over the channels, F, T and C solve both (the
 * look carries F, so one F for the draw). Otherwise, and for the logic ops
 * that read the destination, only a destination of known colour helps:
 * the clear colour, where nothing drawn since reaches (interp_dest.c);
 * there GL's result per vertex is exact when the draw's colour is one per
 * face (flat shading or one colour) or the operation is linear in it.
 *
 * This applies where the vertex colours are GL's fragment colours: unlit
 * or vertex-lit faces, lines and points, untextured and unfogged. Lit,
 * textured or fogged draws keep interp_prim.c's mapping and its notes.
 */
#include "interp_internal.h"

/* ---- State ------------------------------------------------------------------ */

bool interp_blend_factor_ok(GLenum f)
{
    switch (f) {
    case GL_ZERO: case GL_ONE: case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR:
    case GL_DST_COLOR: case GL_ONE_MINUS_DST_COLOR: case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA: case GL_ONE_MINUS_DST_ALPHA:
    case GL_SRC_ALPHA_SATURATE: case GL_CONSTANT_COLOR: case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA: case GL_ONE_MINUS_CONSTANT_ALPHA:
        return true;
    default:
        return false;
    }
}

static bool equation_ok(GLenum m)
{
    return m == GL_FUNC_ADD || m == GL_FUNC_SUBTRACT || m == GL_FUNC_REVERSE_SUBTRACT ||
           m == GL_MIN || m == GL_MAX;
}

void interp_blendfunc(interp *ip, const rgl_cmd *cmd)
{
    GLenum s = arg_enum(cmd, 0), d = arg_enum(cmd, 1);
    if (!interp_blend_factor_ok(s) || !interp_blend_factor_ok(d)) {
        interp_bad_enum(ip, "blend factor", interp_blend_factor_ok(s) ? d : s);
        return;
    }
    ip->st.a.color_buffer.blend_src = ip->st.a.color_buffer.blend_src_alpha = s;
    ip->st.a.color_buffer.blend_dst = ip->st.a.color_buffer.blend_dst_alpha = d;
}

/* The alpha factors change only the framebuffer's alpha, which the
 * picture does not show (a later GL_DST_ALPHA reads it: interp_dest_draw
 * knows only the clear colour's). */
void interp_blendfuncseparate(interp *ip, const rgl_cmd *cmd)
{
    GLenum f[4];
    for (uint32_t k = 0; k < 4; k++) {
        f[k] = arg_enum(cmd, k);
        if (!interp_blend_factor_ok(f[k])) {
            interp_bad_enum(ip, "blend factor", f[k]);
            return;
        }
    }
    ip->st.a.color_buffer.blend_src = f[0];
    ip->st.a.color_buffer.blend_dst = f[1];
    ip->st.a.color_buffer.blend_src_alpha = f[2];
    ip->st.a.color_buffer.blend_dst_alpha = f[3];
}

/* GL 1.4 (ARB_imaging in Mesa's compatibility context). */
void interp_blendequation(interp *ip, const rgl_cmd *cmd)
{
    GLenum m = arg_enum(cmd, 0);
    if (!equation_ok(m)) {
        interp_bad_enum(ip, "blend equation", m);
        return;
    }
    ip->st.a.color_buffer.blend_equation = ip->st.a.color_buffer.blend_equation_alpha = m;
}

void interp_blendequationseparate(interp *ip, const rgl_cmd *cmd)
{
    GLenum m = arg_enum(cmd, 0), ma = arg_enum(cmd, 1);
    if (!equation_ok(m) || !equation_ok(ma)) {
        interp_bad_enum(ip, "blend equation", equation_ok(m) ? ma : m);
        return;
    }
    ip->st.a.color_buffer.blend_equation = m;
    ip->st.a.color_buffer.blend_equation_alpha = ma;
}

/* GL 2.1 4.1.8: the constant colour is clamped to [0, 1]. */
void interp_blendcolor(interp *ip, const rgl_cmd *cmd)
{
    for (int k = 0; k < 4; k++)
        ip->st.a.color_buffer.blend_color[k] = clamp01((float)arg_num(&cmd->arg[k]));
}

/* The sixteen logic ops, GL_CLEAR .. GL_SET (GL 1.1 table 4.3). */
void interp_logicop(interp *ip, const rgl_cmd *cmd)
{
    GLenum op = arg_enum(cmd, 0);
    if (op < GL_CLEAR || op > GL_SET) {
        interp_bad_enum(ip, "logic op", op);
        return;
    }
    ip->st.a.color_buffer.logic_op = op;
}

/* ---- A draw's colours --------------------------------------------------------- */

/* The factors interp_prim.c maps itself (of the source alpha alone). */
static bool alpha_factor(GLenum f)
{
    return f == GL_ZERO || f == GL_ONE || f == GL_SRC_ALPHA || f == GL_ONE_MINUS_SRC_ALPHA;
}

int interp_blend_begin(interp *ip, GLenum mode)
{
    const gl_attribs *a = &ip->st.a;
    const uint8_t *c = a->caps;
    ip->prim_fx = false;
    ip->prim_filter = 0;
    bool logic = c[INTERP_CAP_COLOR_LOGIC_OP];
    GLenum op = a->color_buffer.logic_op;
    if (!logic && !c[INTERP_CAP_BLEND])
        return -1;
    if (logic && op == GL_COPY)
        return SCENE_BLEND_OPAQUE; /* blending is off while the logic op is on */
    if (!logic && a->color_buffer.blend_equation == GL_FUNC_ADD &&
        alpha_factor(a->color_buffer.blend_src) && alpha_factor(a->color_buffer.blend_dst))
        return -1;
    bool final = !(c[INTERP_CAP_LIGHTING] && mode > GL_LINE_STRIP && !interp_vertex_lit(ip)) &&
                 ip->draw_unit[0] < 0 && !c[INTERP_CAP_FOG];
    if (!final) {
        if (!logic)
            return -1; /* interp_prim.c's mapping and notes */
        interp_note(ip, DIAG_NOTE_LOGIC_OP);
        return SCENE_BLEND_OPAQUE; /* drawn as GL_COPY */
    }
    ip->prim_fx = true;
    return SCENE_BLEND_ALPHA; /* the colours as they are, alpha included, until glEnd */
}

/* A source-only factor's weight for channel i (0..2), or the alpha's. */
static bool src_weight(GLenum f, const float c[4], const float K[4], int i, double *w)
{
    switch (f) {
    case GL_ZERO: *w = 0; return true;
    case GL_ONE: *w = 1; return true;
    case GL_SRC_COLOR: *w = c[i]; return true;
    case GL_ONE_MINUS_SRC_COLOR: *w = 1 - (double)c[i]; return true;
    case GL_SRC_ALPHA: *w = c[3]; return true;
    case GL_ONE_MINUS_SRC_ALPHA: *w = 1 - (double)c[3]; return true;
    case GL_CONSTANT_COLOR: *w = K[i]; return true;
    case GL_ONE_MINUS_CONSTANT_COLOR: *w = 1 - (double)K[i]; return true;
    case GL_CONSTANT_ALPHA: *w = K[3]; return true;
    case GL_ONE_MINUS_CONSTANT_ALPHA: *w = 1 - (double)K[3]; return true;
    default: return false;
    }
}

/* GL's result of colour c as E + M d per channel; false where it is not
 * affine in d (GL_MIN, GL_MAX, destination factors on d). */
static bool affine_of(const gl_attribs *a, const float c[4], double e[3], double m[3])
{
    GLenum eq = a->color_buffer.blend_equation;
    GLenum src = a->color_buffer.blend_src, dst = a->color_buffer.blend_dst;
    const float *K = a->color_buffer.blend_color;
    if (eq == GL_MIN || eq == GL_MAX)
        return false;
    for (int i = 0; i < 3; i++) {
        double w, se, sm, dm;
        if (src_weight(src, c, K, i, &w))
            se = w * c[i], sm = 0;
        else if (src == GL_DST_COLOR)
            se = 0, sm = c[i];
        else if (src == GL_ONE_MINUS_DST_COLOR)
            se = c[i], sm = -(double)c[i];
        else
            return false;
        if (!src_weight(dst, c, K, i, &dm))
            return false;
        if (eq == GL_FUNC_ADD)
            e[i] = se, m[i] = sm + dm;
        else if (eq == GL_FUNC_SUBTRACT)
            e[i] = se, m[i] = sm - dm;
        else
            e[i] = -se, m[i] = dm - sm;
    }
    return true;
}

/* Any factor's weight for channel i with destination d (GL 2.1 table 4.2). */
static double weight(GLenum f, const double c[4], const double d[4], const float K[4], int i)
{
    switch (f) {
    case GL_DST_COLOR: return d[i];
    case GL_ONE_MINUS_DST_COLOR: return 1 - d[i];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 1 - d[3];
    case GL_SRC_ALPHA_SATURATE: return fmin(c[3], 1 - d[3]);
    default: {
        float cf[4] = {(float)c[0], (float)c[1], (float)c[2], (float)c[3]};
        double w = 0;
        src_weight(f, cf, K, i, &w);
        return w;
    }
    }
}

/* What the framebuffer holds: 8 bits a channel, rounded in single
 * precision as Mesa converts (0.9f * 255 is 229.5 there, and 230). */
static unsigned q8(double x) { return (unsigned)(clamp01((float)x) * 255.0f + 0.5f); }

static uint8_t logic8(GLenum op, unsigned s, unsigned d)
{
    unsigned r;
    switch (op) {
    case GL_CLEAR: r = 0; break;
    case GL_AND: r = s & d; break;
    case GL_AND_REVERSE: r = s & ~d; break;
    case GL_COPY: r = s; break;
    case GL_AND_INVERTED: r = ~s & d; break;
    case GL_NOOP: r = d; break;
    case GL_XOR: r = s ^ d; break;
    case GL_OR: r = s | d; break;
    case GL_NOR: r = ~(s | d); break;
    case GL_EQUIV: r = ~(s ^ d); break;
    case GL_INVERT: r = ~d; break;
    case GL_OR_REVERSE: r = s | ~d; break;
    case GL_COPY_INVERTED: r = ~s; break;
    case GL_OR_INVERTED: r = ~s | d; break;
    case GL_NAND: r = ~(s & d); break;
    default: r = 0xff; break; /* GL_SET */
    }
    return (uint8_t)(r & 0xff);
}

/* GL's colour over destination d (8-bit values, as the framebuffer
 * holds them). */
static void over_dest(const gl_attribs *a, bool logic, const float cin[4], const float dbg[4],
                      float out[3])
{
    double c[4], d[4];
    for (int k = 0; k < 4; k++) {
        c[k] = q8(cin[k]) / 255.0;
        d[k] = q8(dbg[k]) / 255.0;
    }
    for (int i = 0; i < 3; i++) {
        if (logic) {
            out[i] = logic8(a->color_buffer.logic_op, q8(c[i]), q8(d[i])) / 255.0f;
            continue;
        }
        GLenum eq = a->color_buffer.blend_equation;
        double s = weight(a->color_buffer.blend_src, c, d, a->color_buffer.blend_color, i) * c[i];
        double t = weight(a->color_buffer.blend_dst, c, d, a->color_buffer.blend_color, i) * d[i];
        double r = eq == GL_FUNC_ADD             ? s + t
                   : eq == GL_FUNC_SUBTRACT      ? s - t
                   : eq == GL_FUNC_REVERSE_SUBTRACT ? t - s
                   : eq == GL_MIN                ? fmin(c[i], d[i])
                                                 : fmax(c[i], d[i]);
        out[i] = clamp01((float)r);
    }
}

/* The logic ops of the source alone, as a colour of c (SET, CLEAR,
 * COPY_INVERTED), or NOOP. False for those that read the destination. */
static bool logic_source_only(GLenum op, const float c[4], float out[3], bool *invisible)
{
    *invisible = op == GL_NOOP;
    if (op != GL_CLEAR && op != GL_SET && op != GL_COPY_INVERTED && op != GL_NOOP)
        return false;
    for (int i = 0; i < 3; i++)
        out[i] = logic8(op, q8(c[i]), 0) / 255.0f;
    return true;
}

/* Operations whose second application changes nothing (the draw may then
 * cover a pixel twice). */
static bool idempotent(const gl_attribs *a, bool logic)
{
    if (!logic)
        return a->color_buffer.blend_equation == GL_MIN || a->color_buffer.blend_equation == GL_MAX;
    GLenum op = a->color_buffer.logic_op;
    return op == GL_AND || op == GL_OR || op == GL_AND_INVERTED || op == GL_OR_INVERTED;
}

#define EPS 1e-6

/* M = sl E + t over the three channels, sl >= 0 and 0 <= t < 1: the
 * filter a surface with transmit t can add (F C + t with C = E / s). */
static bool line_fit(const double e[3], const double m[3], double *sl, double *t)
{
    int lo = 0, hi = 0;
    for (int i = 1; i < 3; i++) {
        lo = e[i] < e[lo] ? i : lo;
        hi = e[i] > e[hi] ? i : hi;
    }
    if (!(e[hi] - e[lo] > 1e-4))
        return false;
    *sl = (m[hi] - m[lo]) / (e[hi] - e[lo]);
    *t = m[lo] - *sl * e[lo];
    for (int i = 0; i < 3; i++)
        if (fabs(m[i] - (*sl * e[i] + *t)) >= 1e-4)
            return false;
    return *sl >= 0 && *t > -EPS && *t < 1;
}

void interp_blend_end(interp *ip, uint32_t n)
{
    if (!ip->prim_fx)
        return;
    ip->prim_fx = false;
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    scene_vertex *v = s->verts + ip->prim_first;
    bool logic = a->caps[INTERP_CAP_COLOR_LOGIC_OP];
    /* a filter needs a mesh's look: faces filled on both sides */
    bool faces = ip->prim_mode > GL_LINE_STRIP && a->polygon.mode[0] == GL_FILL &&
                 a->polygon.mode[1] == GL_FILL;
    if (n == 0)
        return;

    if (logic) {
        bool invisible = false;
        float r[3];
        if (logic_source_only(a->color_buffer.logic_op, v[0].color, r, &invisible)) {
            ip->prim_blend = invisible ? SCENE_BLEND_INVISIBLE : SCENE_BLEND_OPAQUE;
            for (uint32_t k = 0; k < n; k++) {
                logic_source_only(a->color_buffer.logic_op, v[k].color, r, &invisible);
                memcpy(v[k].color, r, sizeof r);
                v[k].color[3] = invisible ? 0 : 1;
            }
            return;
        }
    } else {
        /* E + M d: one M (transmit), E zero (filter), or M affine in E. */
        bool affine = true, scalar = true, zero_e = true, in_range = true;
        for (uint32_t k = 0; k < n && affine; k++) {
            double e[3], m[3];
            affine = affine_of(a, v[k].color, e, m);
            for (int i = 0; affine && i < 3; i++) {
                scalar = scalar && fabs(m[i] - m[0]) < EPS;
                zero_e = zero_e && fabs(e[i]) < EPS;
                in_range = in_range && m[i] > -EPS && m[i] < 1 + EPS;
            }
        }
        if (affine && in_range && (scalar || (zero_e && faces))) {
            bool all_invisible = true;
            for (uint32_t k = 0; k < n; k++) {
                double e[3], m[3];
                affine_of(a, v[k].color, e, m);
                if (zero_e && !scalar) { /* filter: behind times M */
                    for (int i = 0; i < 3; i++)
                        v[k].color[i] = (float)fmax(0, fmin(1, m[i]));
                    v[k].color[3] = 0;
                    all_invisible = false;
                    continue;
                }
                double t = fmax(0, fmin(1, m[0]));
                bool adds = !(fabs(e[0]) < EPS && fabs(e[1]) < EPS && fabs(e[2]) < EPS);
                if (t > 1 - 1.0 / 128 && adds) {
                    t = 1 - 1.0 / 128; /* all of what is behind kept: see map_blend */
                    interp_note_pov(ip, DIAG_NOTE_BLEND_ADD, DIAG_NOTE_GLTF_BLEND_ADD);
                }
                all_invisible = all_invisible && !adds && t >= 1 - EPS;
                for (int i = 0; i < 3; i++)
                    v[k].color[i] = t < 1 ? (float)(e[i] / (1 - t)) : 0;
                v[k].color[3] = (float)(1 - t);
            }
            ip->prim_filter = zero_e && !scalar ? 1 : 0;
            ip->prim_blend = all_invisible ? SCENE_BLEND_INVISIBLE : SCENE_BLEND_ALPHA;
            return;
        }
        if (affine && in_range && faces) {
            /* M = a E + T per vertex: F = a s, s = 1 - F - T, one F. */
            double F0 = -1;
            bool fits = true;
            for (uint32_t k = 0; k < n && fits; k++) {
                double e[3], m[3], sl, t;
                affine_of(a, v[k].color, e, m);
                fits = line_fit(e, m, &sl, &t);
                double F = sl * (1 - t) / (1 + sl);
                fits = fits && (F0 < 0 || fabs(F - F0) < 1e-4);
                F0 = F0 < 0 ? F : F0;
            }
            if (fits && F0 >= 0) {
                for (uint32_t k = 0; k < n; k++) {
                    double e[3], m[3], sl, t;
                    affine_of(a, v[k].color, e, m);
                    line_fit(e, m, &sl, &t);
                    double sw = 1 - F0 - fmax(0, t);
                    for (int i = 0; i < 3; i++)
                        v[k].color[i] = sw > EPS ? (float)(e[i] / sw) : 0;
                    v[k].color[3] = (float)fmax(0, sw);
                }
                ip->prim_filter = (float)F0;
                ip->prim_blend = SCENE_BLEND_ALPHA;
                return;
            }
        }
    }

    /* The destination's colour, where it is the clear colour everywhere. */
    float bg[4];
    bool one_colour = true;
    for (uint32_t k = 1; k < n && one_colour; k++)
        one_colour = memcmp(v[k].color, v[0].color, sizeof v[0].color) == 0;
    one_colour = one_colour || a->lighting.shade_model == GL_FLAT;
    if (!one_colour && !logic &&
        (a->color_buffer.blend_equation == GL_MIN || a->color_buffer.blend_equation == GL_MAX) &&
        interp_dest_draw(ip, n, false, bg)) {
        /* min and max are linear where every vertex lies on one side of d */
        one_colour = true;
        for (int i = 0; i < 3 && one_colour; i++) {
            double d = q8(bg[i]) / 255.0;
            bool below = false, above = false;
            for (uint32_t k = 0; k < n; k++) {
                double c = q8(v[k].color[i]) / 255.0;
                below = below || c < d;
                above = above || c > d;
            }
            one_colour = !(below && above);
        }
    }
    if (one_colour && interp_dest_draw(ip, n, !idempotent(a, logic), bg)) {
        for (uint32_t k = 0; k < n; k++) {
            float r[3];
            over_dest(a, logic, v[k].color, bg, r);
            memcpy(v[k].color, r, sizeof r);
            v[k].color[3] = 1;
        }
        ip->prim_blend = SCENE_BLEND_OPAQUE;
        return;
    }
    if (logic) {
        interp_note(ip, DIAG_NOTE_LOGIC_OP);
        ip->prim_blend = SCENE_BLEND_OPAQUE; /* drawn as GL_COPY */
        for (uint32_t k = 0; k < n; k++)
            v[k].color[3] = 1;
        return;
    }
    interp_note(ip, DIAG_NOTE_BLEND_DEST); /* drawn as GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA */
    ip->prim_blend = SCENE_BLEND_ALPHA;
}
