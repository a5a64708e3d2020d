/* interp_stencil.c: the stencil test (GL 1.x 4.1.5): glStencilFunc,
 * glStencilOp, glStencilMask, glClearStencil, and the common pattern.
 *
 * A ray tracer has no stencil buffer, but the common use draws shapes
 * into it (often with colour writes off) and then draws content where it
 * is or is not set: a window, a mirror, a cut-out. The interpreter keeps
 * the buffer as one region: the eye-space triangles drawn into it since
 * its last clear, all holding one value, the clear value elsewhere. A
 * later draw is tested against both values: where the test passes only
 * inside, the draw is kept to the region (the writer clips it by the
 * region's cone of rays from the eye, which holds exactly the pixels
 * whose centres the triangles cover, as GL's stencil does); only outside,
 * to the rest; nowhere, it is left out. Writes of other values over the
 * region, lines and points written into it, fail/zfail operations and
 * regions of more than STENCIL_REGION_MAX triangles are not followed (the
 * draw is drawn as if the test passed): a note says so.
 *
 * A scissored clear (GL 2.1 4.2.3: only the scissor box is cleared) makes
 * the box the region when nothing was written since the last clear, adds
 * the box to the region when it clears to the region's value, and cuts the
 * box out of it (in the camera's image) when it clears to the value
 * around; a third value is not followed (noted where a test reads it). The
 * box's triangles lie on rays through its edges, which run between pixel
 * centres, so the region holds exactly the box's pixels.
 */
#include "interp_internal.h"

#include "talloc.h"

#define STENCIL_MAX 255u /* 8 stencil bits, as Mesa's default visuals */

/* Triangles a region may have for draws to be clipped by it: each clipped
 * object is written with one cone per triangle. */
#define STENCIL_REGION_MAX 1024

static bool is_func(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

static bool is_op(GLenum op)
{
    switch (op) {
    case GL_KEEP: case GL_ZERO: case GL_REPLACE: case GL_INCR: case GL_DECR: case GL_INVERT:
    case GL_INCR_WRAP: case GL_DECR_WRAP:
        return true;
    default:
        return false;
    }
}

void interp_stencilfunc(interp *ip, const rgl_cmd *cmd)
{
    GLenum f = arg_enum(cmd, 0);
    if (!is_func(f)) {
        interp_bad_enum(ip, "stencil function", f);
        return;
    }
    int64_t ref = rgl_arg_i(&cmd->arg[1], 0);
    ip->st.a.stencil.func = f;
    ip->st.a.stencil.ref = (int32_t)(ref < 0 ? 0 : ref > (int64_t)STENCIL_MAX ? STENCIL_MAX : ref);
    ip->st.a.stencil.value_mask = (uint32_t)cmd->arg[2].v.u;
}

void interp_stencilop(interp *ip, const rgl_cmd *cmd)
{
    GLenum op[3];
    for (int k = 0; k < 3; k++) {
        op[k] = arg_enum(cmd, k);
        if (!is_op(op[k])) {
            interp_bad_enum(ip, "stencil operation", op[k]);
            return;
        }
    }
    ip->st.a.stencil.fail = op[0];
    ip->st.a.stencil.zfail = op[1];
    ip->st.a.stencil.zpass = op[2];
}

void interp_stencilmask(interp *ip, const rgl_cmd *cmd)
{
    ip->st.a.stencil.write_mask = (uint32_t)cmd->arg[0].v.u;
}

void interp_clearstencil(interp *ip, const rgl_cmd *cmd)
{
    ip->st.a.stencil.clear = (int32_t)(rgl_arg_i(&cmd->arg[0], 0) & STENCIL_MAX);
}

/* Window point (x, y) on the camera's rays, as an eye point. */
static bool window_eye(const interp *ip, double x, double y, double out[3])
{
    double in[4] = {x, y, 0, 1}, o[4];
    mat4_apply(&ip->cam_from_ndc, in, o);
    for (int k = 0; k < 3; k++)
        out[k] = o[3] != 0 ? o[k] / o[3] : NAN;
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

/* Appends the window polygon p (n corners) as a fan of stencil triangles. */
static bool add_window_poly(interp *ip, double (*p)[2], int n)
{
    double e[8][3];
    for (int k = 0; k < n; k++)
        if (!window_eye(ip, p[k][0], p[k][1], e[k]))
            return false;
    for (int k = 1; k + 1 < n; k++) {
        double t[3][3];
        memcpy(t[0], e[0], sizeof t[0]);
        memcpy(t[1], e[k], sizeof t[1]);
        memcpy(t[2], e[k + 1], sizeof t[2]);
        interp_stencil_tri(ip, t);
    }
    return true;
}

static bool add_box(interp *ip, const int32_t b[4])
{
    double p[4][2] = {{b[0], b[1]}, {(double)b[0] + b[2], b[1]},
                            {(double)b[0] + b[2], (double)b[1] + b[3]}, {b[0], (double)b[1] + b[3]}};
    return add_window_poly(ip, p, 4);
}

/* The pending box becomes the region's triangles (the camera is fixed). */
static void make_box(interp *ip)
{
    if (!ip->stencil.box_pending || !ip->camera_fixed || !ip->scene)
        return;
    ip->stencil.box_pending = false;
    ip->stencil.first = ip->scene->nstencil;
    if (!ip->cam_from_ndc_ok || !add_box(ip, ip->stencil.box))
        ip->stencil.mixed = true;
}

/* Clips the convex window polygon p (n corners, at most 7) to the half
 * plane where coordinate axis of a point is on side sg of v. */
static int clip_half(double (*p)[2], int n, int axis, double v, double sg, double (*out)[2])
{
    int m = 0;
    for (int k = 0; k < n; k++) {
        const double *a = p[k], *b = p[(k + 1) % n];
        double da = sg * (a[axis] - v), db = sg * (b[axis] - v);
        if (da >= 0)
            memcpy(out[m++], a, sizeof out[0]);
        if ((da >= 0) != (db >= 0)) {
            double t = da / (da - db);
            out[m][0] = a[0] + t * (b[0] - a[0]);
            out[m][1] = a[1] + t * (b[1] - a[1]);
            m++;
        }
    }
    return m;
}

/* The region without the window box b: each triangle's parts left of,
 * right of, below and above it. False when a triangle cannot be seen in
 * the window (behind the eye). */
static bool cut_box(interp *ip, const int32_t b[4])
{
    scene *s = ip->scene;
    const scene_camera *cam = &s->camera;
    const int32_t *vp = ip->cam_viewport;
    size_t first = ip->stencil.first, last = s->nstencil;
    if (!ip->cam_from_ndc_ok || last - first > STENCIL_REGION_MAX)
        return false;
    double x0 = b[0], y0 = b[1], x1 = (double)b[0] + b[2], y1 = (double)b[1] + b[3];
    ip->stencil.first = last;
    for (size_t i = first; i < last; i++) {
        double w[3][2];
        for (int v = 0; v < 3; v++) {
            double e[3], im[2];
            for (int k = 0; k < 3; k++)
                e[k] = s->stencil_tris[i][3 * v + k];
            if (!scene_camera_project(cam, e, im))
                return false;
            w[v][0] = im[0] + vp[0] + vp[2] / 2.0;
            w[v][1] = im[1] + vp[1] + vp[3] / 2.0;
        }
        double a[8][2], c[8][2], d[8][2];
        int n;
        if ((n = clip_half(w, 3, 0, x0, -1, a)) >= 3 && !add_window_poly(ip, a, n))
            return false;
        if ((n = clip_half(w, 3, 0, x1, 1, a)) >= 3 && !add_window_poly(ip, a, n))
            return false;
        n = clip_half(w, 3, 0, x0, 1, a);
        n = n >= 3 ? clip_half(a, n, 0, x1, -1, c) : 0;
        int m = n >= 3 ? clip_half(c, n, 1, y0, -1, d) : 0;
        if (m >= 3 && !add_window_poly(ip, d, m))
            return false;
        m = n >= 3 ? clip_half(c, n, 1, y1, 1, d) : 0;
        if (m >= 3 && !add_window_poly(ip, d, m))
            return false;
    }
    return true;
}

void interp_stencil_clear_box(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    uint32_t wm = a->stencil.write_mask & STENCIL_MAX;
    uint32_t c0 = (uint32_t)ip->stencil.cleared, v = (uint32_t)ip->stencil.value;
    int32_t out = (int32_t)((c0 & ~wm) | ((uint32_t)a->stencil.clear & wm));
    if (!ip->scene)
        return;
    make_box(ip);
    if (ip->stencil.mixed)
        return;
    if (!ip->stencil.written) {
        if (out == (int32_t)c0)
            return; /* the value it holds already */
        ip->stencil.value = out;
        ip->stencil.written = true;
        memcpy(ip->stencil.box, a->scissor.box, sizeof ip->stencil.box);
        ip->stencil.box_pending = true;
        make_box(ip);
        return;
    }
    int32_t in = (int32_t)((v & ~wm) | ((uint32_t)a->stencil.clear & wm));
    if (in != out) {
        if (in != (int32_t)v || out != (int32_t)c0)
            ip->stencil.mixed = true; /* three values */
        return;
    }
    if (in == (int32_t)v) {
        if (!ip->camera_fixed || !ip->cam_from_ndc_ok || !add_box(ip, a->scissor.box))
            ip->stencil.mixed = true;
    } else if (in == (int32_t)c0) {
        if (!ip->camera_fixed || !cut_box(ip, a->scissor.box))
            ip->stencil.mixed = true;
    } else {
        ip->stencil.mixed = true;
    }
}

void interp_stencil_clear(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    uint32_t wm = a->stencil.write_mask & STENCIL_MAX;
    ip->stencil.first = ip->scene ? ip->scene->nstencil : 0;
    /* the write mask applies to clears too; a partial one keeps old bits */
    ip->stencil.cleared = (int32_t)(((uint32_t)ip->stencil.cleared & ~wm) |
                                    ((uint32_t)a->stencil.clear & wm));
    ip->stencil.written = false;
    ip->stencil.mixed = false;
    ip->stencil.box_pending = false;
}

static bool test(GLenum f, uint32_t ref, uint32_t s)
{
    switch (f) {
    case GL_NEVER: return false;
    case GL_LESS: return ref < s;
    case GL_LEQUAL: return ref <= s;
    case GL_GREATER: return ref > s;
    case GL_GEQUAL: return ref >= s;
    case GL_EQUAL: return ref == s;
    case GL_NOTEQUAL: return ref != s;
    default: return true;
    }
}

/* The value op leaves over cur, under the write mask. */
static int32_t apply(const gl_attribs *a, GLenum op, int32_t cur)
{
    uint32_t v = (uint32_t)cur;
    switch (op) {
    case GL_ZERO: v = 0; break;
    case GL_REPLACE: v = (uint32_t)a->stencil.ref; break;
    case GL_INCR: v = v < STENCIL_MAX ? v + 1 : v; break;
    case GL_DECR: v = v > 0 ? v - 1 : 0; break;
    case GL_INVERT: v = ~v & STENCIL_MAX; break;
    case GL_INCR_WRAP: v = (v + 1) & STENCIL_MAX; break;
    case GL_DECR_WRAP: v = (v - 1) & STENCIL_MAX; break;
    default: break;
    }
    uint32_t wm = a->stencil.write_mask & STENCIL_MAX;
    return (int32_t)(((uint32_t)cur & ~wm) | (v & wm));
}

bool interp_stencil_writes(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return a->caps[INTERP_CAP_STENCIL_TEST] && (a->stencil.write_mask & STENCIL_MAX) &&
           a->stencil.zpass != GL_KEEP;
}

bool interp_stencil_draw(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    ip->stencil.write = ip->stencil.only = false;
    ip->stencil.clip = 0;
    if (!a->caps[INTERP_CAP_STENCIL_TEST] || !ip->scene)
        return true;
    make_box(ip);
    int32_t out = ip->stencil.cleared;
    int32_t in = ip->stencil.written ? ip->stencil.value : out;
    uint32_t m = a->stencil.value_mask & STENCIL_MAX, ref = (uint32_t)a->stencil.ref & m;
    bool pass_in = test(a->stencil.func, ref, (uint32_t)in & m);
    bool pass_out = test(a->stencil.func, ref, (uint32_t)out & m);
    if (ip->stencil.mixed) {
        interp_note(ip, DIAG_NOTE_STENCIL);
        pass_in = pass_out = true; /* drawn where GL may not */
    }
    ip->stencil.n = ip->scene->nstencil - ip->stencil.first;
    if (ip->stencil.n > STENCIL_REGION_MAX && pass_in != pass_out) {
        /* every clipped object would carry the region's cones */
        interp_note(ip, DIAG_NOTE_STENCIL);
        pass_in = pass_out = true;
    }
    if (pass_in && !pass_out)
        ip->stencil.clip = 1;
    else if (!pass_in && pass_out)
        ip->stencil.clip = 2;
    if ((a->stencil.fail != GL_KEEP && !(pass_in && pass_out)) || a->stencil.zfail != GL_KEEP)
        interp_note(ip, DIAG_NOTE_STENCIL); /* writes where the tests fail */
    if (interp_stencil_writes(ip) && (pass_in || pass_out)) {
        int32_t v_out = apply(a, a->stencil.zpass, out), v_in = apply(a, a->stencil.zpass, in);
        bool changes_in = pass_in && ip->stencil.written && v_in != in;
        bool changes_out = pass_out && v_out != out;
        if (changes_out) {
            if (ip->stencil.written && v_out != ip->stencil.value)
                ip->stencil.mixed = true;
            ip->stencil.value = v_out;
            ip->stencil.written = true;
            ip->stencil.write = true;
        }
        if (changes_in && (!changes_out || v_in != v_out))
            ip->stencil.mixed = true;
        if (ip->stencil.mixed)
            interp_note(ip, DIAG_NOTE_STENCIL);
    }
    return pass_in || pass_out;
}

void interp_stencil_look(interp *ip, scene_look *look)
{
    if (!ip->stencil.clip || !ip->scene)
        return;
    look->stencil_first = (uint32_t)ip->stencil.first;
    look->stencil_n = (uint32_t)ip->stencil.n;
    look->stencil_out = ip->stencil.clip == 2;
}

void interp_stencil_tri(interp *ip, double p[3][3])
{
    scene *s = ip->scene;
    if (!s || s->failed)
        return;
    if (s->nstencil >= UINT32_MAX / 2 ||
        tr_grow((void **)&s->stencil_tris, &s->cap_stencil, s->nstencil + 1,
                sizeof *s->stencil_tris) != 0) {
        s->failed = true;
        return;
    }
    for (int v = 0; v < 3; v++)
        for (int k = 0; k < 3; k++)
            s->stencil_tris[s->nstencil][3 * v + k] = p[v][k];
    s->nstencil++;
}
