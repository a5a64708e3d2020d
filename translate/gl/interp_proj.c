/* interp_proj.c: the frame's camera when a frame uses several projections,
 * and the screen-space layers of the others.
 *
 * A frame may draw a full-window background in glOrtho, then the 3D scene
 * with gluPerspective, then a HUD in window pixels. The camera is the 3D
 * scene's projection: every draw votes for its projection and viewport,
 * weighted by how much it is a 3D draw (depth-tested, lit); the choice
 * prefers a perspective projection with 3D draws, then the most votes.
 * When the first draw fixed another camera, frame.c translates the frame
 * again with the chosen one preset.
 *
 * The other projections' draws are remapped into the camera through the
 * window (interp_prim.c), keeping GL's window depth, so depth-tested ones
 * meet the scene as in GL's depth buffer. One made with the depth test off
 * writes no depth: it covers what was drawn before it and is covered by
 * what is drawn after. While nothing but such draws was made since the
 * frame's start or the last colour clear, it is a background (placed just
 * in front of the far plane); after other draws, an overlay (a HUD: just
 * behind the near plane). Overlapping triangles and quads of one draw made
 * without the depth test each get a step of their own, in order. A
 * depth-tested draw of another projection made
 * before any draw of the camera's and followed by a depth clear is a
 * background too (the first translation sees the clear, the second
 * places it). Draw order within a layer is the painter's
 * (docs/mapping.md "Projections, depth and draw order").
 *
 * The picture is the window the frame stands for: the union of the
 * viewports of its draws and colour clears since its last full colour
 * clear. When that is wider than the camera's viewport (a split screen),
 * the frame is translated again with it preset and the camera's
 * projection widened to it (interp_proj_widen_camera); the camera's own
 * draws stay its own (own_proj, own_vp).
 */
#include "interp_internal.h"

#include <string.h>

/* Where the layers sit between the camera's near (0) and far (1) planes,
 * measured along the view axis in eye space. */
#define LAYER_FRONT 0.001
#define LAYER_BACK 0.999

static bool is_perspective(const mat4 *p) { return p->m[3] != 0 || p->m[7] != 0 || p->m[11] != 0; }

void interp_proj_begin_frame(interp *ip)
{
    ip->nvotes = 0;
    ip->cam_preset = false;
    ip->preset_back_cleared = false;
    ip->back_open = true;
    ip->own_drawn = false;
    ip->draw_seq = 0;
    ip->nclear_seq = 0;
    ip->depth_epoch = ip->depth_epochs = 0;
    ip->epoch_drawn = false;
    ip->win_n = 0;
    ip->win_preset = false;
}

void interp_proj_window_add(interp *ip)
{
    const int32_t *vp = ip->st.a.viewport.rect;
    if (vp[2] < 1 || vp[3] < 1)
        return;
    if (ip->win_n == 0) {
        memcpy(ip->win, vp, sizeof ip->win);
        ip->win_n = 1;
        return;
    }
    int64_t x0 = vp[0] < ip->win[0] ? vp[0] : ip->win[0];
    int64_t y0 = vp[1] < ip->win[1] ? vp[1] : ip->win[1];
    int64_t x1 = (int64_t)vp[0] + vp[2], y1 = (int64_t)vp[1] + vp[3];
    int64_t wx1 = (int64_t)ip->win[0] + ip->win[2], wy1 = (int64_t)ip->win[1] + ip->win[3];
    x1 = x1 > wx1 ? x1 : wx1;
    y1 = y1 > wy1 ? y1 : wy1;
    if (x1 - x0 > INTERP_MAX_VIEWPORT || y1 - y0 > INTERP_MAX_VIEWPORT)
        return; /* no window that large: the viewports are not one window's */
    ip->win[0] = (int32_t)x0;
    ip->win[1] = (int32_t)y0;
    ip->win[2] = (int32_t)(x1 - x0);
    ip->win[3] = (int32_t)(y1 - y0);
    ip->win_n++;
}

bool interp_proj_window(const interp *ip, int32_t win[4])
{
    if (ip->frame_begin || !ip->camera_fixed || ip->win_n < 2)
        return false;
    /* The window's pixels start at 0, 0: viewports reaching below it are
     * cut there, unless the camera's own does (then it is the picture). */
    const int32_t *ov = ip->own_vp;
    int64_t x0 = ip->win[0], y0 = ip->win[1];
    int64_t x1 = x0 + ip->win[2], y1 = y0 + ip->win[3];
    x0 = x0 < 0 ? (ov[0] < 0 ? ov[0] : 0) : x0;
    y0 = y0 < 0 ? (ov[1] < 0 ? ov[1] : 0) : y0;
    if (x1 <= x0 || y1 <= y0)
        return false;
    int32_t w[4] = {(int32_t)x0, (int32_t)y0, (int32_t)(x1 - x0), (int32_t)(y1 - y0)};
    if (memcmp(w, ov, sizeof w) == 0)
        return false;
    memcpy(win, w, sizeof w);
    return true;
}

void interp_proj_preset_window(interp *ip, const int32_t win[4])
{
    ip->win_preset = true;
    memcpy(ip->win_preset_rect, win, sizeof ip->win_preset_rect);
}

void interp_proj_widen_camera(interp *ip)
{
    if (!ip->win_preset || ip->frame_begin)
        return;
    const int32_t *v = ip->own_vp, *w = ip->win_preset_rect;
    if (v[2] < 1 || v[3] < 1 || w[2] < 1 || w[3] < 1)
        return;
    /* The window's NDC of the viewport's: x' = x vw / ww + (2 (vx - wx)
     * + vw) / ww - 1, on clip coordinates (times w_c); so for y. Window
     * x, y and depth stay GL's. */
    mat4 s = mat4_identity();
    s.m[0] = (double)v[2] / w[2];
    s.m[5] = (double)v[3] / w[3];
    s.m[12] = (2.0 * ((double)v[0] - w[0]) + v[2]) / w[2] - 1;
    s.m[13] = (2.0 * ((double)v[1] - w[1]) + v[3]) / w[3] - 1;
    ip->cam_proj = mat4_mul(&s, &ip->own_proj);
    memcpy(ip->cam_viewport, w, sizeof ip->cam_viewport);
}

void interp_proj_clear(interp *ip)
{
    ip->depth_epoch = 0;
    ip->epoch_drawn = false;
    ip->nvotes = 0; /* the scene starts over: so does the choice */
    ip->win_n = 0;
    ip->back_open = true;
    ip->own_drawn = false;
    ip->nclear_seq = 0;
}

void interp_proj_depth_clear(interp *ip)
{
    /* Clears before the camera's first draw leave backgrounds, which the
     * layers place (interp_proj_layer). */
    if (ip->epoch_drawn && ip->own_drawn && ip->depth_epoch < UINT32_MAX) {
        ip->depth_epoch++;
        ip->epoch_drawn = false;
    }
    if (ip->nclear_seq < INTERP_PROJ_VOTES)
        ip->clear_seq[ip->nclear_seq++] = ip->draw_seq;
}

void interp_proj_own_draw(interp *ip)
{
    ip->back_open = false;
    ip->own_drawn = true;
}

void interp_proj_vote(interp *ip, GLenum mode)
{
    interp_proj_window_add(ip);
    const gl_attribs *a = &ip->st.a;
    const mat4 *proj = interp_matrix(ip, INTERP_PROJ);
    const int32_t *vp = a->viewport.rect;
    bool depth = a->caps[INTERP_CAP_DEPTH_TEST];
    bool lit = a->caps[INTERP_CAP_LIGHTING] && mode > GL_LINE_STRIP;
    interp_proj_vote_t *v = NULL;
    for (int i = 0; i < ip->nvotes && !v; i++)
        if (memcmp(ip->votes[i].vp, vp, sizeof ip->votes[i].vp) == 0 &&
            mat4_equal_f32(&ip->votes[i].proj, proj))
            v = &ip->votes[i];
    if (!v) {
        if (ip->nvotes >= INTERP_PROJ_VOTES)
            return; /* a frame of many projections: the first ones choose */
        v = &ip->votes[ip->nvotes++];
        memset(v, 0, sizeof *v);
        v->proj = *proj;
        memcpy(v->vp, vp, sizeof v->vp);
        v->first_seq = ip->draw_seq;
    }
    if (depth && !v->depth_drawn) {
        v->depth_drawn = true;
        v->first_depth_seq = ip->draw_seq;
    }
    if (ip->draw_seq < UINT32_MAX)
        ip->draw_seq++;
    v->solid |= depth || lit;
    uint64_t w = 1 + (depth ? 2 : 0) + (lit ? 4 : 0);
    v->score = v->score + w < v->score ? UINT64_MAX : v->score + w;
}

bool interp_proj_choice(const interp *ip, mat4 *proj, int32_t vp[4], bool *back_cleared)
{
    *back_cleared = false;
    if (ip->frame_begin || !ip->camera_fixed)
        return false;
    int best = -1;
    for (int i = 0; i < ip->nvotes; i++) {
        const interp_proj_vote_t *v = &ip->votes[i];
        if (!v->solid || !mat4_finite(&v->proj))
            continue;
        if (best < 0) {
            best = i;
            continue;
        }
        const interp_proj_vote_t *b = &ip->votes[best];
        bool pv = is_perspective(&v->proj), pb = is_perspective(&b->proj);
        if ((pv && !pb) || (pv == pb && v->score > b->score))
            best = i;
    }
    if (best < 0)
        return false;
    const interp_proj_vote_t *b = &ip->votes[best];
    if (memcmp(b->vp, ip->own_vp, sizeof b->vp) == 0 && mat4_equal_f32(&b->proj, &ip->own_proj))
        return false;
    /* A depth-tested draw of another projection, then a depth clear, both
     * before the camera's first draw: that draw is a background. */
    for (int i = 0; i < ip->nvotes; i++) {
        const interp_proj_vote_t *e = &ip->votes[i];
        if (i == best || !e->depth_drawn || e->first_depth_seq >= b->first_seq)
            continue;
        for (int k = 0; k < ip->nclear_seq; k++)
            if (ip->clear_seq[k] > e->first_depth_seq && ip->clear_seq[k] <= b->first_seq)
                *back_cleared = true;
    }
    *proj = b->proj;
    memcpy(vp, b->vp, sizeof b->vp);
    return true;
}

uint32_t interp_proj_depth_epochs(const interp *ip, const mat4 *proj, const int32_t vp[4])
{
    if (ip->depth_epochs || !ip->camera_fixed || ip->frame_begin)
        return 0;
    if (!proj) {
        proj = &ip->own_proj;
        vp = ip->own_vp;
    }
    /* As the second translation will count them, with this camera: the
     * depth clears after its first draw with draws before them (since
     * the last counted one) and after them. */
    uint32_t first = UINT32_MAX;
    for (int i = 0; i < ip->nvotes; i++)
        if (memcmp(ip->votes[i].vp, vp, sizeof ip->votes[i].vp) == 0 &&
            mat4_equal_f32(&ip->votes[i].proj, proj))
            first = ip->votes[i].first_seq;
    uint32_t n = 0, last = first;
    for (int k = 0; k < ip->nclear_seq; k++) {
        uint32_t c = ip->clear_seq[k];
        if (first != UINT32_MAX && c > last && c < ip->draw_seq) {
            n++;
            last = c;
        }
    }
    return n;
}

void interp_proj_preset_epochs(interp *ip, uint32_t n) { ip->depth_epochs = n; }

bool interp_proj_depth_map(interp *ip, mat4 *w)
{
    ip->epoch_drawn = true;
    const gl_attribs *a = &ip->st.a;
    /* The camera's near and far planes are window depths 0 and 1. */
    double n = ip->frame_begin ? 0 : a->viewport.near, f = ip->frame_begin ? 1 : a->viewport.far;
    /* u, the window depth, 0..1; epoch e of E lies at (E - e + u) / (E + 1);
     * back to NDC: 2 u' - 1 = a z + b. */
    double e = ip->depth_epoch < ip->depth_epochs ? ip->depth_epoch : ip->depth_epochs;
    double E = ip->depth_epochs;
    double sa = (f - n) / (E + 1);
    double sb = (f + n + 2 * (E - e)) / (E + 1) - 1;
    /* A range of one depth makes the draws coplanar: GL_LESS keeps the
     * first one's pixels, GL_LEQUAL the last's; a step per draw, far
     * below a depth buffer's, orders them so. */
    GLenum df = a->depth.func;
    if (f == n && a->caps[INTERP_CAP_DEPTH_TEST] && (df == GL_LESS || df == GL_LEQUAL))
        sb += (df == GL_LESS ? 1e-7 : -1e-7) * fmin(ip->draw_seq, 1e5);
    if (sa == 1 && sb == 0)
        return false;
    for (int k = 0; k < 4; k++)
        w->m[4 * k + 2] = sa * w->m[4 * k + 2] + sb * w->m[4 * k + 3];
    return true;
}

void interp_proj_preset(interp *ip, const mat4 *proj, const int32_t vp[4], bool back_cleared)
{
    ip->cam_preset = true;
    ip->preset_back_cleared = back_cleared;
    ip->cam_preset_proj = *proj;
    memcpy(ip->cam_preset_vp, vp, sizeof ip->cam_preset_vp);
}

/* The NDC depth of the point a fraction t from the near to the far plane
 * on the camera's central ray. */
static bool layer_depth(const interp *ip, double t, double *z)
{
    const int32_t *vp = ip->cam_viewport;
    double c[2] = {vp[0] + vp[2] / 2.0, vp[1] + vp[3] / 2.0}, e[2][4];
    for (int k = 0; k < 2; k++) {
        double in[4] = {c[0], c[1], k ? 1 : -1, 1};
        mat4_apply(&ip->cam_from_ndc, in, e[k]);
        if (!(e[k][3] != 0) || !isfinite(e[k][3]))
            return false;
        for (int j = 0; j < 3; j++)
            e[k][j] /= e[k][3];
    }
    double p[4] = {0, 0, 0, 1}, o[4];
    for (int j = 0; j < 3; j++)
        p[j] = e[0][j] + t * (e[1][j] - e[0][j]);
    mat4 w = interp_window_matrix(&ip->cam_proj, ip->cam_viewport);
    mat4_apply(&w, p, o);
    if (!(o[3] != 0) || !isfinite(o[2] / o[3]))
        return false;
    *z = o[2] / o[3];
    return true;
}

void interp_proj_layer(interp *ip, mat4 *w)
{
    const gl_attribs *a = &ip->st.a;
    if (!ip->cam_from_ndc_ok)
        return;
    if (a->caps[INTERP_CAP_DEPTH_TEST]) {
        if (!(ip->preset_back_cleared && !ip->own_drawn)) {
            ip->back_open = false;
            return; /* GL tests and writes its depth: keep it */
        }
    }
    double z;
    if (!layer_depth(ip, ip->back_open ? LAYER_BACK : LAYER_FRONT, &z))
        return;
    /* z_ndc = z for every point: the z row becomes z times the w row. */
    for (int k = 0; k < 4; k++)
        w->m[4 * k + 2] = z * w->m[4 * k + 3];
}

void interp_proj_end_frame(interp *ip)
{
    scene *s = ip->scene;
    if (!s || !s->have_camera || s->camera.kind != SCENE_CAMERA_ORTHOGRAPHIC)
        return;
    /* The painter's shift moves draws toward an orthographic camera, which
     * sits on GL's near plane: the near plane lets the shift through and
     * the camera steps back past it, as a ray starting on a surface does
     * not see it (with zNear = 0 every draw sits on the camera). */
    scene_camera *cam = &s->camera;
    double reach = interp_painter_reach(ip);
    double dl = sqrt(cam->direction[0] * cam->direction[0] +
                     cam->direction[1] * cam->direction[1] +
                     cam->direction[2] * cam->direction[2]);
    if (!(dl > 0) || !isfinite(dl))
        return;
    for (int k = 0; k < 3; k++)
        cam->location[k] -= cam->direction[k] / dl * 2 * reach;
    if (cam->has_clip)
        cam->clip[0][3] += reach;
}

void interp_proj_painter_prims(interp *ip, GLenum mode, uint32_t n)
{
    const gl_attribs *a = &ip->st.a;
    if (mode != GL_TRIANGLES && mode != GL_QUADS)
        return; /* strips and fans share vertices; their parts rarely overlap */
    if (a->caps[INTERP_CAP_DEPTH_TEST] && (a->depth.func == GL_LESS || a->depth.func == GL_LEQUAL))
        return;
    uint32_t per = mode == GL_TRIANGLES ? 3 : 4, np = n / per;
    if (np < 2 || !ip->scene)
        return;
    /* Primitive j of the draw gets the painter's shift of draw k + j:
     * object -> eye with shift k, back out of shift k, into k + j, and
     * back to object space, where the pool's vertices are. */
    mat4 from_eye, s0 = mat4_identity(), s0inv;
    interp_painter_apply(ip, ip->painter, &s0);
    if (!mat4_invert(&ip->prim_to_eye, &from_eye) || !mat4_invert(&s0, &s0inv))
        return;
    scene_vertex *v = ip->scene->verts + ip->prim_first;
    for (uint32_t j = 1; j < np; j++) {
        uint32_t k = ip->painter + j < INTERP_PAINTER_MAX ? ip->painter + j : INTERP_PAINTER_MAX;
        mat4 m = mat4_identity();
        interp_painter_apply(ip, k, &m);
        m = mat4_mul(&m, &s0inv);
        m = mat4_mul(&m, &ip->prim_to_eye);
        m = mat4_mul(&from_eye, &m);
        for (uint32_t i = j * per; i < (j + 1) * per; i++) {
            double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, o[4];
            mat4_apply(&m, in, o);
            if (!(o[3] != 0))
                continue;
            for (int c = 0; c < 3; c++) {
                double p = o[c] / o[3];
                if (isfinite(p))
                    v[i].pos[c] = (float)p;
            }
        }
    }
    uint32_t k = ip->painter + np - 1;
    ip->painter = k < INTERP_PAINTER_MAX && k >= ip->painter ? k : INTERP_PAINTER_MAX;
}
