/* interp_dest.c: what the colour buffer holds where a draw lands, for the
 * operations that read it (GL 2.1 4.1.8 blending with GL_MIN, GL_MAX,
 * GL_FUNC_SUBTRACT and destination factors; 4.1.10 logic ops).
 *
 * A ray tracer knows what lies behind a surface only as light that passes
 * through it. The one case where the translator knows the destination's
 * colour is the frame's clear colour: the frame cleared the colour buffer
 * and nothing drawn since reaches into the draw's footprint. So the scene's
 * content is kept as rectangles in the camera's image (pixels, origin at
 * the centre, x right, y up), made lazily from the scene itself when a
 * draw asks (nothing is paid by frames that never ask): a rectangle per run
 * of a mesh's triangles, per line, point, solid and list instance, the
 * overlay of pixel rectangles and the scissored clears. A draw whose
 * footprint meets none of them sees the clear colour everywhere.
 *
 * A draw may also meet itself: a strip that folds over, two quads of one
 * glBegin, a strip of wide lines at its joints. An operation that is not
 * idempotent (XOR twice is no XOR) needs each pixel once; interp_dest_draw
 * tells whether the draw's primitives overlap, by separating axes between
 * their image-space polygons.
 */
#include "interp_internal.h"

#include "talloc.h"

/* Rectangles kept per frame; beyond, every pixel counts as drawn. */
#define DEST_RECTS_MAX 65536
/* Primitives of one draw tested pairwise for overlap; beyond, they are
 * taken to overlap. */
#define DEST_SELF_MAX 512
/* A pixel's margin around footprints: edges that share a pixel centre. */
#define DEST_MARGIN 1.0

struct interp_dest {
    uint64_t generation; /* the scene's, when the rectangles below were made */
    size_t meshes, last_tris; /* meshes made into rectangles, triangles of the last */
    size_t lines, points, solids, instances;
    bool overlay;
    uint32_t clear_rects;
    bool all; /* something could not be placed: every pixel counts as drawn */
    double (*rect)[6]; /* x0, y0, x1, y1, and the depth range z0, z1 */
    size_t nrect, cap;
    /* The frame's depth clears since its last colour clear: the window
     * box each cleared and the rectangles drawn before it. */
#define DEST_DEPTH_CLEARS 64
    struct {
        double box[4];
        size_t mark;
    } dclear[DEST_DEPTH_CLEARS];
    uint32_t ndclear;
    bool dclear_lost; /* more than DEST_DEPTH_CLEARS, or one not placed */
    double item[6];   /* one item's box being made */
};

void interp_dest_free(interp *ip)
{
    if (ip->dest) {
        tr_free(ip->dest->rect);
        tr_free(ip->dest);
        ip->dest = NULL;
    }
}

static void box_empty(double b[6])
{
    b[0] = b[1] = b[4] = INFINITY;
    b[2] = b[3] = b[5] = -INFINITY;
}

static bool box_set(const double b[4]) { return b[0] <= b[2] && b[1] <= b[3]; }

static void box_add(double b[4], double x, double y)
{
    b[0] = fmin(b[0], x);
    b[1] = fmin(b[1], y);
    b[2] = fmax(b[2], x);
    b[3] = fmax(b[3], y);
}

/* Adds eye point p to box b, and its depth along the view to b's depth
 * range: false when p is not in front of the camera. */
static bool box_eye(const scene_camera *cam, double b[6], const double p[3])
{
    double w[2];
    if (!scene_camera_project(cam, p, w) || !isfinite(w[0]) || !isfinite(w[1]))
        return false;
    box_add(b, w[0], w[1]);
    const double *d = cam->direction, *o = cam->location;
    double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double z = dl > 0 ? ((p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1] + (p[2] - o[2]) * d[2]) / dl : 0;
    b[4] = fmin(b[4], z);
    b[5] = fmax(b[5], z);
    return true;
}

static bool to_eye3(const mat4 *m, bool in_eye, const float v[3], double out[3])
{
    if (in_eye) {
        for (int k = 0; k < 3; k++)
            out[k] = v[k];
        return true;
    }
    double in[4] = {v[0], v[1], v[2], 1}, o[4];
    mat4_apply(m, in, o);
    if (!(o[3] > 0))
        return false;
    for (int k = 0; k < 3; k++)
        out[k] = o[k] / o[3];
    return true;
}

static void rect_keep(interp *ip, const double b[6])
{
    struct interp_dest *d = ip->dest;
    if (d->all || !box_set(b))
        return;
    if (d->nrect >= DEST_RECTS_MAX ||
        tr_grow((void **)&d->rect, &d->cap, d->nrect + 1, sizeof *d->rect) != 0) {
        d->all = true;
        return;
    }
    memcpy(d->rect[d->nrect++], b, sizeof d->rect[0]);
}

/* The triangles [t0, t1) of a mesh placed by m (the mesh's own to_eye, or
 * an instance's times it). */
static bool tris_box(const scene *s, const mat4 *m, bool in_eye, size_t t0, size_t t1,
                     double b[6])
{
    for (size_t t = t0; t < t1; t++)
        for (int k = 0; k < 3; k++) {
            double e[3];
            if (!to_eye3(m, in_eye, s->verts[s->tris[t].v[k]].pos, e) || !box_eye(&s->camera, b, e))
                return false;
        }
    return true;
}

/* A solid's object-space bounds (scene.h's kinds), generous. */
static void solid_bounds(const scene_solid *so, double lo[3], double hi[3])
{
    const double *p = so->params;
    double r = 0, z0 = 0, z1 = 0;
    switch (so->kind) {
    case SCENE_SOLID_SPHERE: r = p[0], z0 = -p[0], z1 = p[0]; break;
    case SCENE_SOLID_BOX:
        for (int k = 0; k < 3; k++)
            lo[k] = -fabs(p[k]), hi[k] = fabs(p[k]);
        return;
    case SCENE_SOLID_CONE: r = fmax(fabs(p[0]), fabs(p[1])), z0 = fmin(0, p[2]), z1 = fmax(0, p[2]); break;
    case SCENE_SOLID_TORUS: r = fabs(p[0]) + fabs(p[1]), z0 = -fabs(p[1]), z1 = fabs(p[1]); break;
    case SCENE_SOLID_DISC: r = fabs(p[0]); break;
    case SCENE_SOLID_TEAPOT: r = 3 * fabs(p[0]), z0 = -r, z1 = r; break;
    }
    lo[0] = lo[1] = -r, hi[0] = hi[1] = r;
    lo[2] = z0, hi[2] = z1;
}

/* Scratch box for one item, emptied (the dest's, one at a time). */
static double *b6(interp *ip)
{
    box_empty(ip->dest->item);
    return ip->dest->item;
}

/* Keeps an item's box; NULL: it could not be placed. */
static void keep_item(interp *ip, const double *b)
{
    if (!b)
        ip->dest->all = true;
    else
        rect_keep(ip, b);
}

/* The image boxes of line, point, solid and list instance i, into the
 * empty box b; NULL when a corner cannot be placed. */
static const double *line_box(const scene *s, size_t i, double b[6])
{
    const scene_line *l = &s->lines[i];
    for (int e = 0; e < 2; e++)
        for (int sg = -1; sg <= 1; sg += 2) {
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = (double)l->p[e][k] + sg * (double)l->half[e][k];
            if (!box_eye(&s->camera, b, p))
                return NULL;
        }
    return b;
}

static const double *point_box(const scene *s, size_t i, double b[6])
{
    const scene_point *pt = &s->points[i];
    for (int c = 0; c < 4; c++) {
        double p[3];
        for (int k = 0; k < 3; k++)
            p[k] = (double)pt->p[k] + (c & 1 ? 1 : -1) * (double)pt->right[k] +
                   (c & 2 ? 1 : -1) * (double)pt->up[k];
        if (!box_eye(&s->camera, b, p))
            return NULL;
    }
    return b;
}

static const double *solid_box(const scene *s, size_t i, double b[6])
{
    const scene_solid *so = &s->solids[i];
    double lo[3], hi[3];
    solid_bounds(so, lo, hi);
    for (int c = 0; c < 8; c++) {
        float v[3] = {(float)(c & 1 ? hi[0] : lo[0]), (float)(c & 2 ? hi[1] : lo[1]),
                      (float)(c & 4 ? hi[2] : lo[2])};
        double e[3];
        if (!to_eye3(&so->to_eye, false, v, e) || !box_eye(&s->camera, b, e))
            return NULL;
    }
    return b;
}

static const double *instance_box(const scene *s, size_t i, double b[6])
{
    const scene_instance *in = &s->instances[i];
    if (in->proto >= s->nprotos)
        return NULL;
    const scene_proto *pr = &s->protos[in->proto];
    for (size_t k = 0; k < pr->nmeshes && pr->first_mesh + k < s->nmeshes; k++) {
        const scene_mesh *m = &s->meshes[pr->first_mesh + k];
        mat4 place = mat4_mul(&in->to_eye, &m->to_eye);
        if (m->in_eye || !tris_box(s, &place, false, m->first_tri, m->first_tri + m->tri_count, b))
            return NULL;
    }
    return b;
}

/* The box of the overlay's drawn pixels, in front of everything; its
 * pixel (0, 0) at window offset (ox, oy) from the image's. */
static void overlay_box(const scene *s, double ox, double oy, double b[6])
{
    double W = s->camera.width - 2 * ox, H = s->camera.height - 2 * oy;
    box_empty(b);
    for (int y = 0; y < s->overlay_h; y++)
        for (int x = 0; x < s->overlay_w; x++)
            if (s->overlay[((size_t)y * (size_t)s->overlay_w + (size_t)x) * 4 + 3]) {
                box_add(b, x - W / 2, y - H / 2);
                box_add(b, x + 1 - W / 2, y + 1 - H / 2);
            }
    b[4] = b[5] = 0;
}

/* Brings the rectangles up to the scene's content. */
static void sync(interp *ip)
{
    struct interp_dest *d = ip->dest;
    const scene *s = ip->scene;
    const scene_camera *cam = &s->camera;
    if (d->generation != s->generation || s->nmeshes < d->meshes || s->nlines < d->lines ||
        s->npoints < d->points || s->nsolids < d->solids || s->ninstances < d->instances ||
        ip->nclear_rects < d->clear_rects) {
        /* The scene was cleared or cut back (an accumulation pass):
         * made again from the start. */
        d->generation = s->generation;
        d->meshes = d->last_tris = d->lines = d->points = d->solids = d->instances = 0;
        d->overlay = false;
        d->clear_rects = 0;
        d->all = false;
        d->nrect = 0;
        d->ndclear = 0; /* a colour clear erased what they cleared under */
        d->dclear_lost = false;
    }
    if (d->all)
        return;
    /* The last mesh made into rectangles may have grown since. */
    size_t from = d->meshes;
    if (from > 0 && s->meshes[from - 1].tri_count > d->last_tris)
        from--;
    for (size_t i = from; i < s->nmeshes && !d->all; i++) {
        const scene_mesh *m = &s->meshes[i];
        size_t done = i + 1 == d->meshes ? d->last_tris : 0;
        if (m->proto || m->tri_count <= done)
            continue;
        double b[6];
        box_empty(b);
        if (!tris_box(s, &m->to_eye, m->in_eye, m->first_tri + done, m->first_tri + m->tri_count, b))
            d->all = true;
        rect_keep(ip, b);
    }
    if (s->nmeshes > 0) {
        d->meshes = s->nmeshes;
        d->last_tris = s->meshes[s->nmeshes - 1].tri_count;
    }
    for (; d->lines < s->nlines && !d->all; d->lines++)
        keep_item(ip, line_box(s, d->lines, b6(ip)));
    for (; d->points < s->npoints && !d->all; d->points++)
        keep_item(ip, point_box(s, d->points, b6(ip)));
    for (; d->solids < s->nsolids && !d->all; d->solids++)
        keep_item(ip, solid_box(s, d->solids, b6(ip)));
    for (; d->instances < s->ninstances && !d->all; d->instances++)
        keep_item(ip, instance_box(s, d->instances, b6(ip)));
    double W = cam->width, H = cam->height;
    if (s->overlay && !d->overlay) {
        double b[6];
        overlay_box(s, 0, 0, b);
        rect_keep(ip, b);
        d->overlay = true;
    }
    for (; d->clear_rects < ip->nclear_rects; d->clear_rects++) {
        const int32_t *bx = ip->clear_rects[d->clear_rects].box;
        double b[6] = {(double)bx[0] - ip->cam_viewport[0] - W / 2,
                       (double)bx[1] - ip->cam_viewport[1] - H / 2,
                       (double)bx[0] + bx[2] - ip->cam_viewport[0] - W / 2,
                       (double)bx[1] + bx[3] - ip->cam_viewport[1] - H / 2, INFINITY, INFINITY};
        rect_keep(ip, b);
    }
}

/* ---- The draw's own footprint ---------------------------------------------- */

/* A primitive of the open draw as a convex polygon in the camera's image. */
typedef struct dest_poly {
    double p[4][2];
    int n;
} dest_poly;

/* Image position of pool vertex i of the open primitive. */
static bool vertex_image(const interp *ip, size_t i, double out[2])
{
    const scene *s = ip->scene;
    double e[3];
    return to_eye3(&ip->prim_to_eye, false, s->verts[ip->prim_first + i].pos, e) &&
           scene_camera_project(&s->camera, e, out) && isfinite(out[0]) && isfinite(out[1]);
}

/* The draw's primitives (as interp_prim.c assembles them) into polys;
 * false when a vertex cannot be placed or there are more than cap. */
static bool draw_polys(const interp *ip, uint32_t n, dest_poly *polys, size_t cap, size_t *np)
{
    const gl_attribs *a = &ip->st.a;
    GLenum mode = ip->prim_mode;
    *np = 0;
    double (*w)[2] = tr_realloc(NULL, (n ? n : 1) * sizeof *w);
    if (!w)
        return false;
    bool ok = true;
    for (uint32_t i = 0; i < n && ok; i++)
        ok = vertex_image(ip, i, w[i]);
#define EMIT(k, ...)                                                          \
    do {                                                                      \
        const uint32_t v_[] = {__VA_ARGS__};                                  \
        if (*np >= cap) {                                                     \
            ok = false;                                                       \
            break;                                                            \
        }                                                                     \
        dest_poly *q_ = &polys[(*np)++];                                      \
        q_->n = (k);                                                          \
        for (int j_ = 0; j_ < (k); j_++)                                      \
            memcpy(q_->p[j_], w[v_[j_]], sizeof q_->p[j_]);                   \
    } while (0)
    if (ok && mode == GL_POINTS) {
        double h = a->point.size * 0.5;
        for (uint32_t i = 0; i < n && ok; i++) {
            if (*np >= cap) {
                ok = false;
                break;
            }
            dest_poly *q = &polys[(*np)++];
            q->n = 4;
            for (int c = 0; c < 4; c++) {
                q->p[c][0] = w[i][0] + ((c == 1 || c == 2) ? h : -h);
                q->p[c][1] = w[i][1] + (c >= 2 ? h : -h);
            }
        }
    } else if (ok && mode <= GL_LINE_STRIP) {
        double h = a->line.width * 0.5;
        uint32_t segs = mode == GL_LINES ? n / 2 : n >= 2 ? n - 1 + (mode == GL_LINE_LOOP) : 0;
        for (uint32_t k = 0; k < segs && ok; k++) {
            uint32_t i0 = mode == GL_LINES ? 2 * k : k, i1 = mode == GL_LINES ? 2 * k + 1 : (k + 1) % n;
            if (*np >= cap) {
                ok = false;
                break;
            }
            /* GL's band: w pixels across the minor axis (GL 2.1 3.4.2). */
            double dx = w[i1][0] - w[i0][0], dy = w[i1][1] - w[i0][1];
            double ox = fabs(dx) >= fabs(dy) ? 0 : h, oy = fabs(dx) >= fabs(dy) ? h : 0;
            dest_poly *q = &polys[(*np)++];
            q->n = 4;
            const double *e[4] = {w[i0], w[i1], w[i1], w[i0]};
            for (int c = 0; c < 4; c++) {
                double sg = c < 2 ? -1 : 1;
                q->p[c][0] = e[c][0] + sg * ox;
                q->p[c][1] = e[c][1] + sg * oy;
            }
        }
    } else if (ok) {
        switch (mode) {
        case GL_TRIANGLES:
            for (uint32_t i = 0; i + 3 <= n && ok; i += 3)
                EMIT(3, i, i + 1, i + 2);
            break;
        case GL_TRIANGLE_STRIP:
            for (uint32_t i = 0; i + 3 <= n && ok; i++)
                EMIT(3, i, i + 1, i + 2);
            break;
        case GL_TRIANGLE_FAN:
            for (uint32_t i = 0; i + 3 <= n && ok; i++)
                EMIT(3, 0, i + 1, i + 2);
            break;
        case GL_QUADS:
            for (uint32_t i = 0; i + 4 <= n && ok; i += 4) {
                EMIT(3, i, i + 1, i + 2);
                EMIT(3, i, i + 2, i + 3);
            }
            break;
        case GL_QUAD_STRIP:
            for (uint32_t i = 0; i + 4 <= n && ok; i += 2) {
                EMIT(3, i, i + 1, i + 3);
                EMIT(3, i, i + 3, i + 2);
            }
            break;
        case GL_POLYGON:
            for (uint32_t i = 1; i + 1 < n && ok; i++)
                EMIT(3, 0, i, i + 1);
            break;
        default:
            break;
        }
    }
#undef EMIT
    tr_free(w);
    return ok;
}

/* Whether convex polygons a and b share area (touching edges do not): no
 * edge of either separates them. */
static bool polys_overlap(const dest_poly *a, const dest_poly *b)
{
    const dest_poly *pr[2] = {a, b};
    for (int s = 0; s < 2; s++) {
        const dest_poly *q = pr[s];
        for (int k = 0; k < q->n; k++) {
            const double *p0 = q->p[k], *p1 = q->p[(k + 1) % q->n];
            double nx = p1[1] - p0[1], ny = p0[0] - p1[0], len = hypot(nx, ny);
            if (!(len > 1e-12))
                continue;
            nx /= len, ny /= len;
            double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
            for (int t = 0; t < 2; t++)
                for (int j = 0; j < pr[t]->n; j++) {
                    double d = pr[t]->p[j][0] * nx + pr[t]->p[j][1] * ny;
                    lo[t] = fmin(lo[t], d);
                    hi[t] = fmax(hi[t], d);
                }
            if (hi[0] <= lo[1] + 1e-6 || hi[1] <= lo[0] + 1e-6)
                return false;
        }
    }
    return true;
}

static bool dest_make(interp *ip)
{
    if (!ip->dest) {
        ip->dest = tr_realloc(NULL, sizeof *ip->dest);
        if (!ip->dest)
            return false;
        memset(ip->dest, 0, sizeof *ip->dest);
        ip->dest->generation = ip->scene->generation - 1; /* made at the first sync */
    }
    return true;
}

bool interp_dest_draw(interp *ip, uint32_t n, bool need_once, float bg[4])
{
    scene *s = ip->scene;
    if (!s || !ip->cleared || ip->accum.active || !ip->camera_fixed || !dest_make(ip))
        return false;
    dest_poly *polys = tr_realloc(NULL, DEST_SELF_MAX * sizeof *polys);
    if (!polys)
        return false;
    size_t np = 0;
    bool ok = draw_polys(ip, n, polys, DEST_SELF_MAX, &np);
    double b[6];
    box_empty(b);
    for (size_t i = 0; ok && i < np; i++)
        for (int k = 0; k < polys[i].n; k++)
            box_add(b, polys[i].p[k][0], polys[i].p[k][1]);
    /* Joints of a line strip of width 1: GL lights them once (3.4.1). */
    bool thin_joints = ip->prim_mode == GL_LINE_STRIP || ip->prim_mode == GL_LINE_LOOP;
    thin_joints = thin_joints && ip->st.a.line.width <= 1.5f;
    for (size_t i = 0; ok && need_once && i < np; i++)
        for (size_t j = i + 1; ok && j < np; j++) {
            bool neighbours = thin_joints && (j == i + 1 || (i == 0 && j == np - 1));
            if (!neighbours && polys_overlap(&polys[i], &polys[j]))
                ok = false;
        }
    tr_free(polys);
    if (!ok || !box_set(b))
        return false;
    sync(ip);
    const struct interp_dest *d = ip->dest;
    if (d->all)
        return false;
    b[0] -= DEST_MARGIN, b[1] -= DEST_MARGIN, b[2] += DEST_MARGIN, b[3] += DEST_MARGIN;
    for (size_t i = 0; i < d->nrect; i++) {
        const double *r = d->rect[i];
        if (r[0] <= b[2] && b[0] <= r[2] && r[1] <= b[3] && b[1] <= r[3])
            return false;
    }
    memcpy(bg, s->background, 4 * sizeof *bg);
    return true;
}

/* ---- Depth clears ------------------------------------------------------------ */

void interp_dest_depth_clear(interp *ip)
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    if (!s || !dest_make(ip))
        return;
    if (!ip->camera_fixed || (s->ntris == 0 && s->nlines == 0 && s->npoints == 0 &&
                              s->nsolids == 0 && s->ninstances == 0))
        return; /* nothing drawn yet, or nothing placed: nothing it clears under */
    sync(ip);
    struct interp_dest *d = ip->dest;
    if (d->ndclear >= DEST_DEPTH_CLEARS || d->all) {
        d->dclear_lost = true;
        return;
    }
    double W = s->camera.width, H = s->camera.height;
    const int32_t *vp = ip->cam_viewport;
    double *b = d->dclear[d->ndclear].box;
    b[0] = -INFINITY, b[1] = -INFINITY, b[2] = INFINITY, b[3] = INFINITY;
    if (a->caps[INTERP_CAP_SCISSOR_TEST] && interp_scissor_cuts(ip, a->viewport.rect)) {
        const int32_t *x = a->scissor.box;
        b[0] = (double)x[0] - vp[0] - W / 2, b[1] = (double)x[1] - vp[1] - H / 2;
        b[2] = (double)x[0] + x[2] - vp[0] - W / 2, b[3] = (double)x[1] + x[3] - vp[1] - H / 2;
    }
    d->dclear[d->ndclear++].mark = d->nrect;
}

/* Whether r and q share area inside box b (open intervals: touching at an
 * edge is not sharing). */
static bool meet_in(const double *r, const double *q, const double *b)
{
    double x0 = fmax(fmax(r[0], q[0]), b[0]), x1 = fmin(fmin(r[2], q[2]), b[2]);
    double y0 = fmax(fmax(r[1], q[1]), b[1]), y1 = fmin(fmin(r[3], q[3]), b[3]);
    return x0 < x1 && y0 < y1;
}

void interp_dest_end_frame(interp *ip)
{
    struct interp_dest *d = ip->dest;
    if (!d || !ip->scene || (d->ndclear == 0 && !d->dclear_lost))
        return;
    sync(ip);
    bool differs = d->dclear_lost || (d->all && d->ndclear > 0);
    /* GL's later draws inside the box pass the depth test where the scene
     * has earlier geometry in front of them: the scene shows the earlier. */
    for (uint32_t c = 0; c < d->ndclear && !differs; c++) {
        size_t mark = d->dclear[c].mark;
        if ((uint64_t)mark * (d->nrect - mark) > (uint64_t)1 << 24) {
            differs = true;
            break;
        }
        for (size_t l = mark; l < d->nrect && !differs; l++)
            for (size_t e = 0; e < mark && !differs; e++)
                differs = d->rect[l][5] > d->rect[e][4] &&
                          meet_in(d->rect[l], d->rect[e], d->dclear[c].box);
    }
    if (differs)
        interp_note(ip, DIAG_NOTE_DEPTH_CLEAR);
    d->ndclear = 0;
    d->dclear_lost = false;
}

static bool meets(const double a[6], const double b[6])
{
    return box_set(a) && box_set(b) && a[0] <= b[2] + DEST_MARGIN && b[0] <= a[2] + DEST_MARGIN &&
           a[1] <= b[3] + DEST_MARGIN && b[1] <= a[3] + DEST_MARGIN;
}

bool interp_dest_after_overlay(const interp *ip, const scene_mark *m)
{
    const scene *s = ip->scene;
    if (!s || !s->overlay)
        return false;
    double ov[6], b[6];
    overlay_box(s, (double)ip->pixels_org[0] - ip->cam_viewport[0],
                (double)ip->pixels_org[1] - ip->cam_viewport[1], ov);
    if (!box_set(ov))
        return false;
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_mesh *me = &s->meshes[i];
        size_t t0 = me->first_tri > m->ntris ? me->first_tri : m->ntris;
        size_t t1 = me->first_tri + me->tri_count;
        if (me->proto || t0 >= t1)
            continue;
        box_empty(b);
        if (!tris_box(s, &me->to_eye, me->in_eye, t0, t1, b) || meets(ov, b))
            return true;
    }
    for (size_t i = m->nlines; i < s->nlines; i++) {
        box_empty(b);
        if (!line_box(s, i, b) || meets(ov, b))
            return true;
    }
    for (size_t i = m->npoints; i < s->npoints; i++) {
        box_empty(b);
        if (!point_box(s, i, b) || meets(ov, b))
            return true;
    }
    for (size_t i = m->nsolids; i < s->nsolids; i++) {
        box_empty(b);
        if (!solid_box(s, i, b) || meets(ov, b))
            return true;
    }
    for (size_t i = m->ninstances; i < s->ninstances; i++) {
        box_empty(b);
        if (!instance_box(s, i, b) || meets(ov, b))
            return true;
    }
    return false;
}
