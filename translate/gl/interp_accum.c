/* interp_accum.c: the accumulation buffer (glAccum, glClearAccum).
 *
 * A program that accumulates draws its frame N times (clear, draw,
 * glAccum(GL_ACCUM or GL_LOAD, 1/N), ...) and then glAccum(GL_RETURN). A
 * scene holds one of those passes, the first: what later passes draw is
 * dropped (scene_truncate) when they are accumulated, cleared or returned.
 * Each later pass's first draw is compared with the first pass's:
 *
 *   - same modelview, projection moved by a sub-pixel translation in
 *     normalised device coordinates: a jittered projection for
 *     antialiasing; the scene asks for POV-Ray's antialiasing;
 *   - the eye moved in its own xy plane with the projection sheared so
 *     that one plane keeps its image (the Red Book's accPerspective depth
 *     of field): the scene asks for POV-Ray's focal blur, focused on that
 *     plane, through a lens as wide as the eyes are spread;
 *   - anything else (motion blur: the geometry moves) is noted, and the
 *     first pass alone is drawn.
 *
 * The scene's passes start from an accumulation buffer of zero over the
 * whole window. A clear to another value (glClearAccum), a clear or a
 * glAccum cut to the scissor box (GL 2.1 4.2.3, 4.2.4: only the box's
 * pixels change), and passes accumulated onto a buffer the frame never
 * cleared are noted where the passes are returned.
 */
#include "interp_internal.h"

#include <string.h>

/* How far apart two passes' eyes or matrices may be and still count as equal. */
#define ACCUM_EPS 1e-5
/* The largest projection jitter that is antialiasing, in pixels. */
#define ACCUM_MAX_JITTER 2.0
/* How far a lens pass's focal plane may stray from the first's (fraction). */
#define ACCUM_FOCUS_SPREAD 0.02

void interp_accum_begin_frame(interp *ip)
{
    memset(&ip->accum, 0, sizeof ip->accum);
    ip->accum.want_draw = true;
}

void interp_accum_draw(interp *ip)
{
    struct interp_accum *a = &ip->accum;
    if (!a->want_draw)
        return;
    a->want_draw = false;
    a->proj = *interp_matrix(ip, INTERP_PROJ);
    a->mv = *interp_matrix(ip, INTERP_MV);
}

/* Window position in pixels of the first pass's eye point q as pass (p, d)
 * sees it: d maps the first pass's eye space to the pass's own. False
 * behind the eye. */
static bool window_of(const interp *ip, const mat4 *p, const mat4 *d, const double q[4],
                      double out[2])
{
    double e[4], c[4];
    mat4_apply(d, q, e);
    mat4_apply(p, e, c);
    if (!(c[3] > 0) || !isfinite(c[0]) || !isfinite(c[1]))
        return false;
    out[0] = c[0] / c[3] * ip->st.a.viewport.rect[2] / 2;
    out[1] = c[1] / c[3] * ip->st.a.viewport.rect[3] / 2;
    return true;
}

/* Where the image of the first pass's eye point q moves, in pixels, from
 * the first pass to the current one. */
static bool shift_at(const interp *ip, const mat4 *d, const double q[4], double out[2])
{
    const struct interp_accum *a = &ip->accum;
    mat4 id = mat4_identity();
    double w0[2], w1[2];
    if (!window_of(ip, &a->proj0, &id, q, w0) || !window_of(ip, &a->proj, d, q, w1))
        return false;
    out[0] = w1[0] - w0[0];
    out[1] = w1[1] - w0[1];
    return true;
}

/* Sorts the current pass (its first draw) against the first pass. */
static void classify_pass(interp *ip)
{
    struct interp_accum *a = &ip->accum;
    mat4 inv0, d;
    if (!mat4_invert(&a->mv0, &inv0)) {
        a->n_other++;
        return;
    }
    d = mat4_mul(&a->mv, &inv0); /* first pass's eye space -> this pass's */
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            if (c < 3 || r == 3)
                if (fabs(d.m[c * 4 + r] - (c == r ? 1 : 0)) > ACCUM_EPS) {
                    a->n_other++;
                    return;
                }
    double t[3] = {d.m[12], d.m[13], d.m[14]};
    double scale = 1 + fabs(a->mv0.m[12]) + fabs(a->mv0.m[13]) + fabs(a->mv0.m[14]);
    double txy = hypot(t[0], t[1]);
    if (txy <= ACCUM_EPS * scale && fabs(t[2]) <= ACCUM_EPS * scale) {
        /* The same eye: the projection moved by a translation of NDC? */
        mat4 pinv, q;
        if (!mat4_invert(&a->proj0, &pinv)) {
            a->n_other++;
            return;
        }
        q = mat4_mul(&a->proj, &pinv);
        for (int i = 0; i < 16; i++)
            if (i != 12 && i != 13 && fabs(q.m[i] - (i % 5 == 0 ? 1 : 0)) > ACCUM_EPS) {
                a->n_other++;
                return;
            }
        double px = fmax(fabs(q.m[12]) * ip->st.a.viewport.rect[2] / 2,
                         fabs(q.m[13]) * ip->st.a.viewport.rect[3] / 2);
        if (px > ACCUM_MAX_JITTER) {
            a->n_other++;
            return;
        }
        a->n_jitter++;
        a->max_jitter = fmax(a->max_jitter, px);
        return;
    }
    if (fabs(t[2]) > 1e-3 * txy) {
        a->n_other++; /* the eye moved along its view axis */
        return;
    }
    /* The eye moved sideways: the image of an axis point at depth z moves
     * by A + B/z pixels; the plane that keeps its image is the focus. */
    int k = fabs(t[0]) >= fabs(t[1]) ? 0 : 1;
    double s1[2], s2[2];
    const double q1[4] = {0, 0, -1, 1}, q2[4] = {0, 0, -2, 1};
    if (!shift_at(ip, &d, q1, s1) || !shift_at(ip, &d, q2, s2)) {
        a->n_other++;
        return;
    }
    double b = 2 * (s1[k] - s2[k]), aa = s1[k] - b;
    double focus = aa != 0 ? -b / aa : -1;
    double sf[2], so[2];
    const double qf[4] = {0, 0, -focus, 1};
    const double qo[4] = {0.3 * focus, -0.2 * focus, -focus, 1};
    if (!(focus > 0) || !isfinite(focus) || !shift_at(ip, &d, qf, sf) ||
        !shift_at(ip, &d, qo, so) || hypot(sf[0], sf[1]) > 0.5 || hypot(so[0], so[1]) > 0.5) {
        a->n_other++;
        return;
    }
    if (a->n_lens == 0 || focus < a->focus_min)
        a->focus_min = focus;
    if (a->n_lens == 0 || focus > a->focus_max)
        a->focus_max = focus;
    a->n_lens++;
    /* This pass's eye, in the first pass's eye space, is at -t. */
    a->eye_sum[0] -= t[0];
    a->eye_sum[1] -= t[1];
    a->eye_sum2 += t[0] * t[0] + t[1] * t[1];
}

/* The passes are returned: what the scene gets in their place. */
static void conclude(interp *ip, double ret)
{
    struct interp_accum *a = &ip->accum;
    scene *s = ip->scene;
    if (a->buffer_odd && ret != 0)
        interp_note(ip, DIAG_NOTE_ACCUM_CLEAR);
    if (a->odd_weights || fabs(a->weight * ret - 1) > 0.02)
        interp_note(ip, DIAG_NOTE_ACCUM_WEIGHTS);
    if (a->passes < 2 || !s)
        return;
    if (a->n_other > 0 || !a->have_first) {
        interp_note(ip, DIAG_NOTE_ACCUM_PASSES);
        return;
    }
    if (a->n_lens > 0) {
        if (a->n_jitter > 0 || a->focus_max - a->focus_min > ACCUM_FOCUS_SPREAD * a->focus_max) {
            interp_note(ip, DIAG_NOTE_ACCUM_PASSES);
            return;
        }
        /* A lens as wide as the eyes: for eyes spread evenly over a disc
         * of radius R, the mean squared distance from their centre is R^2/2. */
        double n = a->passes;
        double mx = a->eye_sum[0] / n, my = a->eye_sum[1] / n;
        double var = a->eye_sum2 / n - mx * mx - my * my;
        double r = sqrt(var > 0 ? 2 * var : 0);
        double focus = (a->focus_min + a->focus_max) / 2;
        s->focal_blur = true;
        s->aperture = 2 * r;
        s->focal_point[0] = 0;
        s->focal_point[1] = 0;
        s->focal_point[2] = -focus;
        s->blur_samples = a->passes < 32 ? 32 : (int)(a->passes < 256 ? a->passes : 256);
        return;
    }
    if (a->n_jitter > 0 && a->max_jitter > 0) {
        int depth = (int)ceil(sqrt((double)a->passes));
        s->antialias_depth = depth < 2 ? 2 : depth > 9 ? 9 : depth;
    }
}

/* Drops what was drawn since the first pass. */
static void drop_pass(interp *ip)
{
    interp_budget_peak(ip);
    if (ip->scene)
        scene_truncate(ip->scene, &ip->accum.mark);
    ip->painter = ip->accum.painter;
}

bool interp_accum_clear(interp *ip)
{
    if (!ip->accum.active)
        return false;
    drop_pass(ip);
    return true;
}

static bool scissored(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return a->caps[INTERP_CAP_SCISSOR_TEST] && interp_scissor_cuts(ip, a->viewport.rect);
}

void interp_accum_buffer_clear(interp *ip)
{
    struct interp_accum *a = &ip->accum;
    const float *c = ip->st.a.accum.clear;
    bool zero = c[0] == 0 && c[1] == 0 && c[2] == 0;
    if (scissored(ip) || !zero)
        a->buffer_odd = true;
    else if (!a->active)
        a->buffer_odd = false; /* all of it zero again */
    a->cleared = true;
}

void interp_accum(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum op = arg_enum(cmd, 0);
    double value = arg_num(&cmd->arg[1]);
    struct interp_accum *a = &ip->accum;
    if (op == GL_ACCUM || op == GL_LOAD || op == GL_RETURN) {
        if (scissored(ip) || (op == GL_ACCUM && !a->active && !a->cleared))
            a->buffer_odd = true;
    }
    switch (op) {
    case GL_ACCUM:
    case GL_LOAD:
        interp_unrec_use(ip, UNREC_USE_READ);
        if (!isfinite(value))
            value = 0;
        if (!a->active) {
            a->active = true;
            a->passes = 1;
            a->weight = value;
            a->have_first = !a->want_draw;
            a->proj0 = a->proj;
            a->mv0 = a->mv;
            if (ip->scene)
                scene_mark_take(ip->scene, &a->mark);
            a->painter = ip->painter;
        } else {
            if (a->have_first && !a->want_draw)
                classify_pass(ip);
            a->passes++;
            a->weight = op == GL_LOAD ? value : a->weight + value;
            drop_pass(ip);
        }
        a->want_draw = true;
        return;
    case GL_MULT:
    case GL_ADD:
        a->odd_weights = true;
        if (!a->active)
            interp_note(ip, DIAG_NOTE_ACCUM_WEIGHTS);
        return;
    case GL_RETURN:
        if (!a->active)
            return;
        drop_pass(ip);
        conclude(ip, isfinite(value) ? value : 0);
        /* Draws after it add to the scene; another accumulation starts over. */
        interp_accum_begin_frame(ip);
        return;
    default:
        interp_bad_enum(ip, "glAccum operation", op);
        return;
    }
}

/* The accumulation buffer's clear value (GL 2.1 4.2.3: clamped to
 * [-1, 1]): a pass accumulated onto it adds to it (interp_accum_buffer_clear). */
void interp_clearaccum(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    for (int k = 0; k < 4; k++) {
        double v = arg_num(&cmd->arg[k]);
        ip->st.a.accum.clear[k] = (float)(v > -1 ? (v < 1 ? v : 1) : -1);
    }
}
