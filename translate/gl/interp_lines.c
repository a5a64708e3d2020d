/* interp_lines.c: lines and points as GL rasterises them, at the frame's
 * size (docs/mapping.md section 7).
 *
 * A segment is clipped as GL clips it (the user planes by the caller, the
 * near and far planes and the viewport's sides here), and its window
 * pixels are found by GL's rule (rasterise.c). They become strips of the
 * window whose edges lie between pixel centres, each taken back into eye
 * space in the plane of the segment and an image axis, at the segment's
 * depth: a ray through a pixel centre then meets a strip exactly where GL
 * lit that pixel. Points become the rectangles of their pixels, at the
 * point's depth. A render at another size, or with antialiasing (rays off
 * the pixel centres), is no longer pixel for pixel.
 */
#include "interp_internal.h"
#include "rasterise.h"
#include "talloc.h"

#include <math.h>
#include <string.h>

/* Unit vectors along the camera's image axes, in eye space. */
static void image_axes(const scene_camera *cam, double r[3], double u[3])
{
    double rl = sqrt(cam->right[0] * cam->right[0] + cam->right[1] * cam->right[1] +
                     cam->right[2] * cam->right[2]);
    double ul = sqrt(cam->up[0] * cam->up[0] + cam->up[1] * cam->up[1] + cam->up[2] * cam->up[2]);
    for (int k = 0; k < 3; k++) {
        r[k] = rl > 0 ? cam->right[k] / rl : (k == 0);
        u[k] = ul > 0 ? cam->up[k] / ul : (k == 1);
    }
}

/* Window position of eye point p (GL's window: origin at the frame's
 * lower left, in pixels). */
static bool window_of(const scene_camera *cam, const double p[3], double w[2])
{
    if (!scene_camera_project(cam, p, w))
        return false;
    w[0] += cam->width * 0.5;
    w[1] += cam->height * 0.5;
    return true;
}

bool interp_gl_window(const interp *ip, const float obj[3], double out[2])
{
    const int32_t *vp = ip->st.a.viewport.rect;
    if (ip->frame_begin || ip->prim_in_eye || !ip->scene ||
        memcmp(vp, ip->own_vp, sizeof ip->own_vp) != 0 ||
        !mat4_equal_f32(interp_matrix(ip, INTERP_PROJ), &ip->own_proj))
        return false;
    /* Measured: Mesa's pixels on 6000 lines with decimal ends, under
     * gluOrtho2D(0, 320, 0, 240) and under a scaled and turned modelview,
     * all agree with these positions; the camera's double mapping missed
     * 1 line in 100 where ends fall on pixel centres and edges. */
    const mat4 *pm = interp_matrix(ip, INTERP_PROJ), *mm = interp_matrix(ip, INTERP_MV);
    float p[16], m[16];
    for (int k = 0; k < 16; k++) {
        p[k] = (float)pm->m[k];
        m[k] = (float)mm->m[k];
    }
    if (!ras_window(p, m, vp[2], vp[3], obj, out))
        return false;
    /* in the picture's window, which may be wider than the viewport */
    out[0] += (double)vp[0] - ip->cam_viewport[0];
    out[1] += (double)vp[1] - ip->cam_viewport[1];
    return true;
}

/* Scratch space for one segment's pixels and strips. */
static bool ras_room(interp *ip, size_t n)
{
    if (n > ip->cap_ras_runs &&
        tr_grow((void **)&ip->ras_runs, &ip->cap_ras_runs, n, sizeof *ip->ras_runs) != 0)
        return false;
    if (n > ip->cap_ras_pieces &&
        tr_grow((void **)&ip->ras_pieces, &ip->cap_ras_pieces, n, sizeof *ip->ras_pieces) != 0)
        return false;
    return true;
}

/* The eye segment's camera coordinates (scene_camera_coords) at its ends,
 * for the window -> segment inversion. */
typedef struct seg_frame {
    const scene_camera *cam;
    double p[2][3];
    double c[2][3];
    bool ortho;
} seg_frame;

/* The fraction along the segment whose window coordinate on axis ax
 * (0 x, 1 y) is m; not clamped (NAN when the segment runs along the ray). */
static double seg_at(const seg_frame *f, int ax, double m)
{
    const scene_camera *cam = f->cam;
    double size = ax == 0 ? cam->width : cam->height;
    double v = m / size - 0.5; /* image coordinate in [-1/2, 1/2] */
    const double *c0 = f->c[0], *c1 = f->c[1];
    int a = ax + 1;
    if (f->ortho) {
        double d = c1[a] - c0[a];
        return d != 0 ? (v - c0[a]) / d : NAN;
    }
    /* (c0[a] + u da) / (c0[0] + u d0) = v */
    double den = (c1[a] - c0[a]) - v * (c1[0] - c0[0]);
    return den != 0 ? (v * c0[0] - c0[a]) / den : NAN;
}

/* The eye point whose window position is (x, y) on the plane through the
 * segment and the image axis across it: the segment's point at fraction
 * u (kept within the segment), moved parallel to the image. */
static bool eye_at(const seg_frame *f, double u, double x, double y, double out[3], double *px,
                   double *py)
{
    const scene_camera *cam = f->cam;
    double uc = isfinite(u) ? fmin(fmax(u, 0), 1) : 0, q[3], w[2], r[3], up[3];
    for (int k = 0; k < 3; k++)
        q[k] = f->p[0][k] + (f->p[1][k] - f->p[0][k]) * uc;
    if (!window_of(cam, q, w) || !scene_camera_pixel_size(cam, q, px, py))
        return false;
    image_axes(cam, r, up);
    for (int k = 0; k < 3; k++)
        out[k] = q[k] + (x - w[0]) * *px * r[k] + (y - w[1]) * *py * up[k];
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

/* Clips eye segment p0-p1 (and its fractions t) to GL's near and far
 * planes, moved in by a hair so that the ends stay inside the frame's
 * clipped_by (which cuts on the same planes). */
static bool clip_depth(const interp *ip, double p[2][3], double t[2])
{
    const scene_camera *cam = &ip->scene->camera;
    double a[3] = {p[0][0], p[0][1], p[0][2]}, b[3] = {p[1][0], p[1][1], p[1][2]};
    double ta = 0, tb = 1;
    for (int k = 0; k < 3; k++) {
        double pl[4];
        if (k < 2) {
            if (!cam->has_clip)
                continue;
            memcpy(pl, cam->clip[k], sizeof pl);
            if (k == 0)
                pl[3] += interp_painter_reach(ip);
        } else {
            if (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC)
                continue;
            /* in front of the eye, whatever the planes say */
            double dl = sqrt(cam->direction[0] * cam->direction[0] +
                             cam->direction[1] * cam->direction[1] +
                             cam->direction[2] * cam->direction[2]);
            if (!(dl > 0))
                return false;
            for (int i = 0; i < 3; i++)
                pl[i] = cam->direction[i] / dl;
            pl[3] = -(pl[0] * cam->location[0] + pl[1] * cam->location[1] +
                      pl[2] * cam->location[2]) - 1e-9 * dl;
        }
        double da = pl[0] * a[0] + pl[1] * a[1] + pl[2] * a[2] + pl[3];
        double db = pl[0] * b[0] + pl[1] * b[1] + pl[2] * b[2] + pl[3];
        if (da < 0 && db < 0)
            return false;
        if (da >= 0 && db >= 0)
            continue;
        double s = da / (da - db);
        s = da < 0 ? fmin(s + 1e-7, 1) : fmax(s - 1e-7, 0);
        double at = ta + (tb - ta) * s;
        for (int i = 0; i < 3; i++) {
            double x = p[0][i] + (p[1][i] - p[0][i]) * at;
            if (da < 0)
                a[i] = x;
            else
                b[i] = x;
        }
        if (da < 0)
            ta = at;
        else
            tb = at;
    }
    if (!(ta < tb))
        return false;
    double t0 = t[0] + (t[1] - t[0]) * ta, t1 = t[0] + (t[1] - t[0]) * tb;
    memcpy(p[0], a, sizeof a);
    memcpy(p[1], b, sizeof b);
    t[0] = t0;
    t[1] = t1;
    return true;
}

/* The draw's viewport in the frame's window coordinates: GL clips to it. */
static void viewport_rect(const interp *ip, double r[4])
{
    const scene_camera *cam = &ip->scene->camera;
    r[0] = r[1] = 0;
    r[2] = cam->width;
    r[3] = cam->height;
    if (ip->frame_begin)
        return;
    const int32_t *vp = ip->st.a.viewport.rect, *cv = ip->cam_viewport;
    r[0] = (double)vp[0] - cv[0];
    r[1] = (double)vp[1] - cv[1];
    r[2] = r[0] + vp[2];
    r[3] = r[1] + vp[3];
}

/* GL's colour along a line at fraction t: linear, carried on past the
 * ends where a strip reaches beyond them (GL clamps each pixel, and so
 * does POV-Ray's output), bounded against wild extrapolation. */
static void lerp_colour(const interp_line *ln, double t, float out[4])
{
    for (int k = 0; k < 4; k++) {
        double c = ln->color[0][k] + (ln->color[1][k] - ln->color[0][k]) * t;
        double lo = k == 3 ? 0 : -1, hi = k == 3 ? 1 : 2; /* alpha: GL's blend weight */
        out[k] = (float)(c < lo ? lo : c > hi ? hi : c);
    }
}

/* One quad of a smooth line: window corners k[0..3] in scene_line's
 * order, a colour each, each corner taken into eye space at the
 * segment's depth where its major coordinate falls. */
static void smooth_quad(interp *ip, const seg_frame *f, int ax, const double k[4][2],
                        const float col[4][4])
{
    double e[4][3], px, py;
    for (int i = 0; i < 4; i++)
        if (!eye_at(f, seg_at(f, ax, k[i][ax]), k[i][0], k[i][1], e[i], &px, &py))
            return;
    scene_line *l = scene_add_line(ip->scene);
    if (!l)
        return;
    static const int pair[2][2] = {{0, 1}, {3, 2}};
    for (int n = 0; n < 2; n++) {
        const double *lo = e[pair[n][0]], *hi = e[pair[n][1]];
        for (int j = 0; j < 3; j++) {
            l->p[n][j] = (float)((lo[j] + hi[j]) * 0.5);
            l->half[n][j] = (float)((hi[j] - lo[j]) * 0.5);
        }
    }
    for (int i = 0; i < 4; i++) {
        memcpy(l->color[i], col[i], sizeof l->color[i]);
        interp_fogsec_eye(ip, e[i], l->color[i]);
    }
}

/* Where an edge of a smooth line's rectangle goes: Mesa's triangles take
 * a pixel centre on a left edge (or on a bottom one, in GL's frame) and
 * leave it on the others; the edge moves out or in by a hair to say so. */
#define SMOOTH_TIE (1.0 / 1024)

/* GL_LINE_SMOOTH, window dash q0-q1 (Mesa's draw module, aaline): a
 * rectangle max(1, w / 2 + 1/2) to each side, half a pixel longer at each
 * end, every pixel in it drawn, GL's colour at its ends (those of the
 * segment's ends, not moved). Its coverage goes into alpha: 1 but for a
 * pixel's width along the rim, down to 0 at the edge; blended
 * (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) that shows, so the rectangle is
 * drawn as a grid of rim, cap and middle quads whose corner alphas ramp as
 * the coverage does (the rim's corners take the middle of the two ramps). */
static void add_smooth(interp *ip, const interp_line *ln, const seg_frame *f, const double q0[2],
                       const double q1[2], const double t[2])
{
    double dx = q1[0] - q0[0], dy = q1[1] - q0[1], len = hypot(dx, dy);
    if (!(len > 0))
        return;
    double c = dx / len, sn = dy / len;
    double hw = ln->width <= 1 ? 1 : ln->width * 0.5 + 0.5, hl = len * 0.5 + 0.5;
    double mid[2] = {(q0[0] + q1[0]) * 0.5, (q0[1] + q1[1]) * 0.5};
    int ax = fabs(dx) >= fabs(dy) ? 0 : 1;
    /* Edge offsets: along (t) and across (s, to the left of the line). */
    double along[2] = {-hl, hl}, across[2] = {-hw, hw};
    for (int side = 0; side < 2; side++) {
        /* outward normals: along (c, sn) * sign, across (-sn, c) * sign */
        double sg = side ? 1 : -1;
        double na[2] = {sg * c, sg * sn}, ns[2] = {-sg * sn, sg * c};
        bool in_a = na[0] < 0 || (na[0] == 0 && na[1] < 0);
        bool in_s = ns[0] < 0 || (ns[0] == 0 && ns[1] < 0);
        along[side] += sg * (in_a ? SMOOTH_TIE : -SMOOTH_TIE);
        across[side] += sg * (in_s ? SMOOTH_TIE : -SMOOTH_TIE);
    }
    /* GL's colour at the rectangle's ends: the dash's ends' own. */
    float col[2][4];
    for (int n = 0; n < 2; n++) {
        double u = seg_at(f, ax, (n ? q1 : q0)[ax]);
        lerp_colour(ln, t[0] + (t[1] - t[0]) * (isfinite(u) ? u : n), col[n]);
    }
    bool ramp = ip->prim_blend == SCENE_BLEND_ALPHA && !ip->prim_blend_mapped;
    /* The grid's lines along (t) and across (s); one cell when unblended. */
    double ts[4], ss[4];
    int nt = 0, ns = 0;
    ts[nt++] = along[0];
    if (ramp && hl > 1)
        ts[nt++] = -(hl - 1), ts[nt++] = hl - 1;
    else if (ramp)
        ts[nt++] = 0;
    ts[nt++] = along[1];
    ss[ns++] = across[0];
    if (ramp && hw > 1)
        ss[ns++] = -(hw - 1), ss[ns++] = hw - 1;
    else if (ramp)
        ss[ns++] = 0;
    ss[ns++] = across[1];
    /* POV-Ray averages a face's corner textures after their transmit (a
     * premultiplied colour), GL multiplies the interpolated colour by the
     * interpolated coverage: where both vary (the rim, colour along it),
     * the cells are cut short enough that they agree within 2/255. */
    double dc = 0;
    for (int q = 0; q < 3; q++)
        dc = fmax(dc, fabs((double)col[1][q] - col[0][q]));
    for (int i = 0; i + 1 < nt; i++)
        for (int j = 0; j + 1 < ns; j++) {
            bool rim = ramp && (j == 0 || j == ns - 2);
            bool cap = ramp && (i == 0 || i == nt - 2);
            double span = (ts[i + 1] - ts[i]) / (2 * hl);
            int cuts = rim ? (int)ceil(dc * span * 255 / 8) : 1;
            cuts = cuts < 1 ? 1 : cuts > 64 ? 64 : cuts;
            /* a rim's corner, where both coverages ramp (their product is
             * not flat): four cells, within 16/255 */
            int across_cuts = rim && cap ? 2 : 1;
            if (rim && cap)
                cuts = 2;
            for (int m = 0; m < cuts * across_cuts; m++) {
            int mt = m / across_cuts, ms = m % across_cuts;
            double ta = ts[i] + (ts[i + 1] - ts[i]) * mt / cuts;
            double tb = mt + 1 == cuts ? ts[i + 1] : ts[i] + (ts[i + 1] - ts[i]) * (mt + 1) / cuts;
            double sa = ss[j] + (ss[j + 1] - ss[j]) * ms / across_cuts;
            double sb = ms + 1 == across_cuts ? ss[j + 1] : ss[j] + (ss[j + 1] - ss[j]) * (ms + 1) / across_cuts;
            double tt[4] = {ta, ta, tb, tb};
            double s4[4] = {sa, sb, sb, sa};
            double k[4][2];
            float cc[4][4];
            for (int v = 0; v < 4; v++) {
                k[v][0] = mid[0] + tt[v] * c - s4[v] * sn;
                k[v][1] = mid[1] + tt[v] * sn + s4[v] * c;
                double u = (tt[v] + hl) / (2 * hl);
                for (int q = 0; q < 4; q++)
                    cc[v][q] = (float)(col[0][q] + (col[1][q] - col[0][q]) * u);
                if (ramp)
                    cc[v][3] *= (float)(fmin(fmax(hw - fabs(s4[v]), 0), 1) *
                                        fmin(fmax(hl - fabs(tt[v]), 0), 1));
            }
            smooth_quad(ip, f, ax, (const double(*)[2])k, (const float(*)[4])cc);
            }
        }
}

/* One strip of a line: along the major axis from m[0] to m[1], with
 * the piece's minor edges, GL's colour at each end (fraction te of the
 * caller's segment, or, where flat, the colour at fraction te[0]). */
static void add_strip(interp *ip, const interp_line *ln, const seg_frame *f, int ax,
                      double slope, const ras_piece *pc, const double m[2], const double te[2],
                      bool flat)
{
    const scene_camera *cam = f->cam;
    double pe[2][3], half[2][3], r[3], up[3];
    image_axes(cam, r, up);
    for (int e = 0; e < 2; e++) {
        double mid = slope * m[e] + (pc->lo + pc->hi) * 0.5;
        double x = ax == 0 ? m[e] : mid, y = ax == 0 ? mid : m[e], px, py;
        if (!eye_at(f, seg_at(f, ax, m[e]), x, y, pe[e], &px, &py))
            return;
        double h = (pc->hi - pc->lo) * 0.5;
        for (int k = 0; k < 3; k++)
            half[e][k] = ax == 0 ? h * py * up[k] : h * px * r[k];
    }
    scene_line *l = scene_add_line(ip->scene);
    if (!l)
        return;
    for (int e = 0; e < 2; e++) {
        for (int k = 0; k < 3; k++) {
            l->p[e][k] = (float)pe[e][k];
            l->half[e][k] = (float)half[e][k];
        }
        lerp_colour(ln, flat ? te[0] : te[e], l->color[2 * e]);
        if (flat)
            for (int k = 0; k < 3; k++)
                l->color[2 * e][k] = fminf(fmaxf(l->color[2 * e][k], 0), 1);
        interp_fogsec_eye(ip, pe[e], l->color[2 * e]);
        memcpy(l->color[2 * e + 1], l->color[2 * e], sizeof l->color[0]);
    }
}

static bool colour_out(const interp_line *ln, double te)
{
    float c[4];
    lerp_colour(ln, te, c);
    return c[0] < 0 || c[0] > 1 || c[1] < 0 || c[1] > 1 || c[2] < 0 || c[2] > 1;
}

/* The strips of window segment q0-q1 (a part of f's segment, whose
 * fractions uq its ends are) as scene lines; t maps f's fractions to the
 * caller's, whose colours they are. A strip ends on the segment's end
 * where that lies between the last pixel centre lit and the next (its
 * colour is then the vertex's own, and the colours of a frame's lines
 * stay few), else on the pixel edge. GL's colour along a line follows
 * the major axis, carried on past an end and clamped per pixel; where
 * that leaves [0, 1] at a strip's end, the end pixel gets a strip of its
 * own in the colour GL gives its centre. */
static void add_pixels(interp *ip, const interp_line *ln, const seg_frame *f, const double q0[2],
                       const double q1[2], const double uq[2], const double t[2])
{
    const scene_camera *cam = f->cam;
    size_t room = (size_t)(cam->width > cam->height ? cam->width : cam->height) + 2;
    if (!ras_room(ip, room)) {
        ip->scene->failed = true;
        return;
    }
    ras_line rl;
    if (!ras_line_pixels(q0[0], q0[1], q1[0], q1[1], ln->width, cam->width, cam->height, &rl,
                         ip->ras_runs, room))
        return;
    int ax = rl.axis;
    double dmaj = q1[ax] - q0[ax], slope = dmaj != 0 ? (q1[1 - ax] - q0[1 - ax]) / dmaj : 0;
    size_t np = ras_line_pieces(&rl, ip->ras_runs, slope, ip->ras_pieces, room);
    /* the dash's ends, lower major coordinate first */
    int lo_end = q0[ax] <= q1[ax] ? 0 : 1;
    const double *qe[2] = {lo_end ? q1 : q0, lo_end ? q0 : q1};
    double ue[2] = {uq[lo_end], uq[1 - lo_end]};
    for (size_t i = 0; i < np; i++) {
        const ras_piece *pc = &ip->ras_pieces[i];
        double m[2] = {pc->a, pc->b}, te[2];
        bool at_vertex[2] = {false, false};
        for (int e = 0; e < 2; e++) {
            bool outer = e == 0 ? i == 0 : i + 1 == np;
            double v = qe[e][ax], edge = m[e];
            if (outer && v >= edge - 0.5 + RAS_MARGIN && v <= edge + 0.5 - RAS_MARGIN) {
                m[e] = v;
                at_vertex[e] = true;
            }
            double u = at_vertex[e] ? ue[e] : seg_at(f, ax, m[e]);
            te[e] = isfinite(u) ? t[0] + (t[1] - t[0]) * u : t[e];
        }
        /* an end strip carried out of [0, 1]: its end pixel alone */
        bool cut[2] = {false, false};
        for (int e = 0; e < 2; e++)
            cut[e] = !at_vertex[e] && pc->b - pc->a > (cut[0] ? 1 : 0) && colour_out(ln, te[e]);
        double mm[2] = {m[0], m[1]}, tm[2] = {te[0], te[1]};
        for (int e = 0; e < 2; e++) {
            if (!cut[e])
                continue;
            double px0 = e == 0 ? pc->a : pc->b - 1, px1 = px0 + 1, c = px0 + 0.5;
            double u = seg_at(f, ax, c), tc[2];
            tc[0] = tc[1] = isfinite(u) ? t[0] + (t[1] - t[0]) * u : te[e];
            double me[2] = {px0, px1};
            add_strip(ip, ln, f, ax, slope, pc, me, tc, true);
            mm[e] = e == 0 ? px1 : px0;
            double uu = seg_at(f, ax, mm[e]);
            tm[e] = isfinite(uu) ? t[0] + (t[1] - t[0]) * uu : te[e];
        }
        if (mm[1] > mm[0])
            add_strip(ip, ln, f, ax, slope, pc, mm, tm, false);
    }
}

uint64_t interp_frame_segments(const interp *ip) { return ip->segments; }

void interp_add_line(interp *ip, const interp_line *ln, double *stipple_counter)
{
    scene *s = ip->scene;
    const scene_camera *cam = &s->camera;
    seg_frame f;
    double t[2] = {0, 1};
    memcpy(f.p, ln->p, sizeof f.p);
    if (!clip_depth(ip, f.p, t))
        return;
    f.cam = cam;
    f.ortho = cam->kind == SCENE_CAMERA_ORTHOGRAPHIC;
    double w[2][2];
    if (!scene_camera_coords(cam, f.p[0], f.c[0]) || !scene_camera_coords(cam, f.p[1], f.c[1]) ||
        !window_of(cam, f.p[0], w[0]) || !window_of(cam, f.p[1], w[1]))
        return;
    /* t now maps f's fractions to the caller's: colours are the caller's. */
    if (ln->have_win && t[0] == 0 && t[1] == 1)
        memcpy(w, ln->win, sizeof w);
    double vr[4], wa, wb;
    viewport_rect(ip, vr);
    if (!ras_clip_line(w, vr, &wa, &wb))
        return; /* the stipple counter runs from the clipped start, as GL's */
    double dash[INTERP_STIPPLE_DASHES][2] = {{0, 1}};
    size_t nd = 1;
    if (ln->stipple)
        nd = interp_stipple_dashes(ip, w[0], w[1], stipple_counter, dash, INTERP_STIPPLE_DASHES);
    int ax = fabs(w[1][0] - w[0][0]) >= fabs(w[1][1] - w[0][1]) ? 0 : 1;
    for (size_t d = 0; d < nd; d++) {
        double q[2][2], uq[2];
        for (int e = 0; e < 2; e++) {
            for (int k = 0; k < 2; k++)
                q[e][k] = dash[d][e] == 1 ? w[1][k] : w[0][k] + (w[1][k] - w[0][k]) * dash[d][e];
            /* f's own ends exactly, else where the window point falls */
            bool end0 = dash[d][e] == 0 && wa == 0, end1 = dash[d][e] == 1 && wb == 1;
            uq[e] = end0 ? 0 : end1 ? 1 : seg_at(&f, ax, q[e][ax]);
        }
        if (ln->smooth)
            add_smooth(ip, ln, &f, q[0], q[1], t);
        else
            add_pixels(ip, ln, &f, q[0], q[1], uq, t);
    }
}

void interp_add_point(interp *ip, const double p[3], const double *win, const float color[4],
                      double size, bool smooth, bool params, bool sprite)
{
    const scene_camera *cam = &ip->scene->camera;
    double w[2], px, py, r[3], u[3];
    if (!window_of(cam, p, w) || !scene_camera_pixel_size(cam, p, &px, &py))
        return;
    if (win)
        w[0] = win[0], w[1] = win[1];
    if (w[0] < 0 || w[0] > cam->width || w[1] < 0 || w[1] > cam->height)
        return;
    for (int k = 0; k < 2 && cam->has_clip; k++)
        if (cam->clip[k][0] * p[0] + cam->clip[k][1] * p[1] + cam->clip[k][2] * p[2] +
                cam->clip[k][3] + (k == 0 ? interp_painter_reach(ip) : 0) < 0)
            return; /* the near plane (0) lets the painter's shift through */
    image_axes(cam, r, u);
    /* GL's point size range here is 1 to 255 (aliased and smooth). */
    size = size > 255 ? 255 : size;
    ras_run rows[256];
    int32_t y0, x0, n;
    size_t nrows;
    float c[4];
    memcpy(c, color, sizeof c);
    interp_fogsec_eye(ip, p, c);
    if (sprite) {
        /* the quad of the size itself: its edges, not a pixel grid, decide
         * which centres it covers, as the textured square does */
        double h = size > 0 ? size * 0.5 : 0.5;
        scene_point *pt = scene_add_point(ip->scene);
        if (!pt)
            return;
        for (int i = 0; i < 3; i++) {
            pt->p[i] = (float)p[i];
            pt->right[i] = (float)(h * px * r[i]);
            pt->up[i] = (float)(h * py * u[i]);
        }
        memcpy(pt->color, c, sizeof pt->color);
        return;
    }
    if (smooth) {
        double d = params ? size : (size < 2 ? 2 : size);
        nrows = ras_point_round(w[0], w[1], d, cam->height, &y0, rows, 256);
    } else {
        ras_point_square(w[0], w[1], size, cam->height, &x0, &y0, &n);
        rows[0] = (ras_run){x0, x0 + n - 1};
        nrows = 1;
    }
    /* One rectangle per run of rows alike (a square point is one). */
    for (size_t k = 0; k < nrows;) {
        size_t j = k + 1;
        while (j < nrows && rows[j].lo == rows[k].lo && rows[j].hi == rows[k].hi)
            j++;
        double xa = rows[k].lo, xb = rows[k].hi + 1.0;
        double ya = y0 + (double)k, yb = smooth ? y0 + (double)j : y0 + (double)n;
        scene_point *pt = scene_add_point(ip->scene);
        if (!pt)
            return;
        double cx = (xa + xb) * 0.5 - w[0], cy = (ya + yb) * 0.5 - w[1];
        for (int i = 0; i < 3; i++) {
            pt->p[i] = (float)(p[i] + cx * px * r[i] + cy * py * u[i]);
            pt->right[i] = (float)((xb - xa) * 0.5 * px * r[i]);
            pt->up[i] = (float)((yb - ya) * 0.5 * py * u[i]);
        }
        memcpy(pt->color, c, sizeof pt->color);
        k = j;
    }
}
