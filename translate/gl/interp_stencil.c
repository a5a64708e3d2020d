/* interp_stencil.c: the stencil test (GL 1.x 4.1.5): glStencilFunc,
 * glStencilOp, glStencilMask, glClearStencil, their two-sided forms
 * (glStencil*Separate, GL 2.0), and the common pattern.
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
 * draw is drawn as if the test passed): a note says so. Two-sided state
 * decides a draw by the face it can show; a draw showing both faces,
 * which the two states treat differently, takes the front's, noted.
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

/* The faces a glStencil*Separate names (GL 2.0 4.1.5), as a mask of
 * face[] (1 front, 2 back); 0 after an invalid enum, said. */
static int faces_of(interp *ip, GLenum face)
{
    switch (face) {
    case GL_FRONT: return 1;
    case GL_BACK: return 2;
    case GL_FRONT_AND_BACK: return 3;
    default:
        interp_bad_enum(ip, "stencil face", face);
        return 0;
    }
}

static void set_func(interp *ip, int faces, const rgl_cmd *cmd, int first)
{
    GLenum f = arg_enum(cmd, first);
    if (!is_func(f)) {
        interp_bad_enum(ip, "stencil function", f);
        return;
    }
    int64_t ref = rgl_arg_i(&cmd->arg[first + 1], 0);
    for (int k = 0; k < 2; k++) {
        if (!(faces & (1 << k)))
            continue;
        struct gl_stencil_face *sf = &ip->st.a.stencil.face[k];
        sf->func = f;
        sf->ref = (int32_t)(ref < 0 ? 0 : ref > (int64_t)STENCIL_MAX ? STENCIL_MAX : ref);
        sf->value_mask = (uint32_t)cmd->arg[first + 2].v.u;
    }
}

static void set_op(interp *ip, int faces, const rgl_cmd *cmd, int first)
{
    GLenum op[3];
    for (int k = 0; k < 3; k++) {
        op[k] = arg_enum(cmd, first + k);
        if (!is_op(op[k])) {
            interp_bad_enum(ip, "stencil operation", op[k]);
            return;
        }
    }
    for (int k = 0; k < 2; k++) {
        if (!(faces & (1 << k)))
            continue;
        struct gl_stencil_face *sf = &ip->st.a.stencil.face[k];
        sf->fail = op[0];
        sf->zfail = op[1];
        sf->zpass = op[2];
    }
}

static void set_mask(interp *ip, int faces, uint32_t mask)
{
    for (int k = 0; k < 2; k++)
        if (faces & (1 << k))
            ip->st.a.stencil.face[k].write_mask = mask;
}

/* The one-sided calls set both faces (GL 2.0). */
void interp_stencilfunc(interp *ip, const rgl_cmd *cmd) { set_func(ip, 3, cmd, 0); }
void interp_stencilop(interp *ip, const rgl_cmd *cmd) { set_op(ip, 3, cmd, 0); }
void interp_stencilmask(interp *ip, const rgl_cmd *cmd)
{
    set_mask(ip, 3, (uint32_t)cmd->arg[0].v.u);
}

void interp_stencilfuncseparate(interp *ip, const rgl_cmd *cmd)
{
    int faces = faces_of(ip, arg_enum(cmd, 0));
    if (faces)
        set_func(ip, faces, cmd, 1);
}

void interp_stencilopseparate(interp *ip, const rgl_cmd *cmd)
{
    int faces = faces_of(ip, arg_enum(cmd, 0));
    if (faces)
        set_op(ip, faces, cmd, 1);
}

void interp_stencilmaskseparate(interp *ip, const rgl_cmd *cmd)
{
    int faces = faces_of(ip, arg_enum(cmd, 0));
    if (faces)
        set_mask(ip, faces, (uint32_t)cmd->arg[1].v.u);
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
    uint32_t wm = a->stencil.face[0].write_mask & STENCIL_MAX;
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
    uint32_t wm = a->stencil.face[0].write_mask & STENCIL_MAX;
    ip->stencil.first = ip->scene ? ip->scene->nstencil : 0;
    /* the (front) write mask applies to clears too; a partial one keeps old
     * bits */
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

/* The value op of face sf leaves over cur, under its write mask. */
static int32_t apply(const struct gl_stencil_face *sf, GLenum op, int32_t cur)
{
    uint32_t v = (uint32_t)cur;
    switch (op) {
    case GL_ZERO: v = 0; break;
    case GL_REPLACE: v = (uint32_t)sf->ref; break;
    case GL_INCR: v = v < STENCIL_MAX ? v + 1 : v; break;
    case GL_DECR: v = v > 0 ? v - 1 : 0; break;
    case GL_INVERT: v = ~v & STENCIL_MAX; break;
    case GL_INCR_WRAP: v = (v + 1) & STENCIL_MAX; break;
    case GL_DECR_WRAP: v = (v - 1) & STENCIL_MAX; break;
    default: break;
    }
    uint32_t wm = sf->write_mask & STENCIL_MAX;
    return (int32_t)(((uint32_t)cur & ~wm) | (v & wm));
}

static bool face_writes(const struct gl_stencil_face *sf)
{
    return (sf->write_mask & STENCIL_MAX) && sf->zpass != GL_KEEP;
}

bool interp_stencil_writes(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return a->caps[INTERP_CAP_STENCIL_TEST] &&
           (face_writes(&a->stencil.face[0]) || face_writes(&a->stencil.face[1]));
}

/* What face sf's state does to a draw over the buffer the scene keeps:
 * where it passes (inside the region, outside it), whether its fail or
 * zfail operations write, and the values its zpass leaves. */
typedef struct stencil_outcome {
    bool pass_in, pass_out, fail_ops, writes;
    int32_t v_in, v_out;
} stencil_outcome;

static stencil_outcome outcome(const interp *ip, const struct gl_stencil_face *sf)
{
    stencil_outcome o;
    int32_t out = ip->stencil.cleared;
    int32_t in = ip->stencil.written ? ip->stencil.value : out;
    uint32_t m = sf->value_mask & STENCIL_MAX, ref = (uint32_t)sf->ref & m;
    o.pass_in = test(sf->func, ref, (uint32_t)in & m);
    o.pass_out = test(sf->func, ref, (uint32_t)out & m);
    o.fail_ops = (sf->fail != GL_KEEP && !(o.pass_in && o.pass_out)) || sf->zfail != GL_KEEP;
    o.writes = face_writes(sf);
    o.v_in = o.writes ? apply(sf, sf->zpass, in) : in;
    o.v_out = o.writes ? apply(sf, sf->zpass, out) : out;
    return o;
}

/* The face whose state decides the draw: the front's, unless only back
 * faces can be drawn (GL_CULL_FACE of GL_FRONT); points, lines, bitmaps and
 * pixels are front-facing (GL 2.0 3.5.1, 4.1.5). A draw that may show both
 * faces, tested alike but written by one face only, writes the region with
 * that face's triangles alone (stencil.tri_faces, interp_prim.c); one tested
 * differently, or written with two values, takes the front's state and is
 * marked two_side (interp_prim.c notes it at a back face drawn). */
static int deciding_face(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    const struct gl_stencil_face *fr = &a->stencil.face[0], *bk = &a->stencil.face[1];
    if (memcmp(fr, bk, sizeof *fr) == 0 || !ip->in_begin || ip->prim_mode <= GL_LINE_STRIP)
        return 0;
    bool cull = a->caps[INTERP_CAP_CULL_FACE];
    bool front = !(cull && (a->polygon.cull_mode == GL_FRONT || a->polygon.cull_mode == GL_FRONT_AND_BACK));
    bool back = !(cull && (a->polygon.cull_mode == GL_BACK || a->polygon.cull_mode == GL_FRONT_AND_BACK));
    if (!back)
        return 0;
    if (!front)
        return 1;
    stencil_outcome of = outcome(ip, fr), ob = outcome(ip, bk);
    bool pass_same = of.pass_in == ob.pass_in && of.pass_out == ob.pass_out &&
                     of.fail_ops == ob.fail_ops;
    bool passes = of.pass_in || of.pass_out;
    bool fw = of.writes && passes, bw = ob.writes && passes;
    bool write_same = (!fw && !bw) || (fw && bw && of.v_in == ob.v_in && of.v_out == ob.v_out);
    if (pass_same && !write_same && fw != bw) {
        ip->stencil.tri_faces = fw ? 1 : 2;
        return fw ? 0 : 1;
    }
    ip->stencil.two_side = !pass_same || !write_same;
    return 0;
}

bool interp_stencil_faces_differ(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return a->caps[INTERP_CAP_STENCIL_TEST] &&
           memcmp(&a->stencil.face[0], &a->stencil.face[1], sizeof a->stencil.face[0]) != 0;
}

bool interp_stencil_draw(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    ip->stencil.write = ip->stencil.only = ip->stencil.two_side = false;
    ip->stencil.tri_faces = 3;
    ip->stencil.clip = 0;
    if (!a->caps[INTERP_CAP_STENCIL_TEST] || !ip->scene)
        return true;
    make_box(ip);
    const struct gl_stencil_face *sf = &a->stencil.face[deciding_face(ip)];
    stencil_outcome o = outcome(ip, sf);
    int32_t out = ip->stencil.cleared;
    int32_t in = ip->stencil.written ? ip->stencil.value : out;
    bool pass_in = o.pass_in, pass_out = o.pass_out;
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
    if (o.fail_ops)
        interp_note(ip, DIAG_NOTE_STENCIL); /* writes where the tests fail */
    if (o.writes && (pass_in || pass_out)) {
        int32_t v_out = apply(sf, sf->zpass, out), v_in = apply(sf, sf->zpass, in);
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
